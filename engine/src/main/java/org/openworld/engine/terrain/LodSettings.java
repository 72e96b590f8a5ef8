package org.openworld.engine.terrain;

import org.openworld.engine.core.Pass;
import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Settings of the terrain's level of detail, keys {@code lod.*}.
 *
 * @param patchVertices  vertices per side of the one vertex grid every patch is drawn with: N + 1 for N = 32 or 64
 *                       cells. A leaf patch covers N × N height samples. 65 is the default: it halves the patches
 *                       per side (a quarter of the draw calls and quadtree nodes) for the same triangle density, and
 *                       draw calls, not vertices, are what a small patch costs; 65² = 4225 vertices still fit 16-bit
 *                       indices
 * @param baseResolution B of the paper's equation 2, L = ⌊log2(D / B)⌋: the distance at which the terrain drops its
 *                       first level of detail. A patch of level L is drawn from B·2^L to B·2^(L+1) away with vertices
 *                       2^L samples apart, so a triangle edge subtends between Δ/(2B) and Δ/B radians at every level
 *                       (Δ the sample spacing), and a full ring of one level holds about 6π(B/Δ)² triangles. The
 *                       default 128 m gives 4–8 pixel edges for 1 m samples at 1080 lines and a 60° view (1030 px
 *                       per radian), about 75 000 visible triangles per level; larger is finer and costlier
 * @param mode           quadtree cut (the default, patch count logarithmic in the world size) or the paper's flat
 *                       grid (for figure 6)
 * @param reflectionCoarsening levels coarser in the water's reflection pass: the reflection is drawn at half
 *                       resolution and seen wobbling on the ripples, so detail finer than its pixels cannot be seen;
 *                       each level halves B there, a quarter of the triangles
 * @param shadowCoarsening levels coarser in the sun's shadow pass, with distances from the viewer's eye: a shadow is
 *                       seen through the map's texels and the PCF filter, which blur detail finer than a few texels,
 *                       and a coarser caster moves its shadow's edge by less than that; each level halves B there
 */
public record LodSettings(
        @Setting(doc = "vertices per patch side (33 or 65)", min = 33, max = 65, atStart = true) int patchVertices,
        @Setting(doc = "base resolution B: distance of the first level drop", unit = "m", min = 1, max = 100000)
        double baseResolution,
        @Setting(doc = "level-of-detail scheme: QUADTREE or FLAT_GRID (the paper's, figure 6)") LodMode mode,
        @Setting(doc = "levels coarser in the water's reflection pass", min = 0, max = 4) int reflectionCoarsening,
        @Setting(doc = "levels coarser in the sun's shadow pass", min = 0, max = 4) int shadowCoarsening) {

    public static final LodSettings DEFAULTS = new LodSettings(65, 128, LodMode.QUADTREE, 1, 1);

    public static final SettingsGroup<LodSettings> SETTINGS = SettingsGroup.of("lod", LodSettings.class, DEFAULTS);

    public LodSettings {
        if (patchVertices != 33 && patchVertices != 65) {
            throw new IllegalArgumentException("patch vertices must be 33 or 65, got " + patchVertices);
        }
        if (!(baseResolution > 0)) {
            throw new IllegalArgumentException("base resolution must be positive, got " + baseResolution);
        }
        if (mode == null) {
            throw new IllegalArgumentException("level-of-detail mode missing");
        }
    }

    /** B in a pass: coarser by {@link #reflectionCoarsening()} levels in the water's reflection, by
     *  {@link #shadowCoarsening()} in the sun's shadow pass. */
    public double baseResolution(Pass pass) {
        return switch (pass) {
            case REFLECTION -> baseResolution / (1 << reflectionCoarsening);
            case SHADOW -> baseResolution / (1 << shadowCoarsening);
            default -> baseResolution;
        };
    }

    /** Cells per patch side, N = {@link #patchVertices()} − 1. */
    public int cells() {
        return patchVertices - 1;
    }
}

package org.openworld.engine.terrain.lod;

import org.openworld.engine.core.Pass;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Settings of the terrain's level of detail, keys {@code lod.*}.
 *
 * @param patchVertices  vertices per side of the one vertex grid every patch is drawn with: N + 1 for N = 16, 32 or
 *                       64 cells. A leaf patch covers N × N height samples. 33 is the default: the screen-error rule
 *                       refines a whole patch wherever any part of it needs it, so smaller patches put the triangles
 *                       closer to where the relief shows. Measured in the peer comparison's view (1280 × 720): 33
 *                       gives 74 k triangles at 4 px, 65 gives 147 k at 4 px and the same 74 k only at 8 px. 65
 *                       has a quarter of the patches and quadtree nodes, but patches are drawn instanced, one call
 *                       per index pattern, so the count costs little. 17 (the low preset's) goes one step further:
 *                       on {@code valley.path} at 1280 × 720 with the low preset, 74 k triangles in the viewer's pass
 *                       instead of 118 k under the same pixel bound, four times the patches; a side stitches at most
 *                       four levels (log2 16), and on the unbounded world the tree has one level more
 * @param rule           when a patch is fine enough: SCREEN_ERROR (the default) bounds its geometric error on
 *                       screen, PAPER is the paper's distance rule (figure 6)
 * @param pixelError     the screen-error rule's bound in the viewer's and the reflection's passes: a patch is drawn
 *                       at its level once its geometric error e, at the distance D of its box, covers at most this
 *                       many pixels, e · (H/2) / (tan(fov/2) · D) ≤ pixelError (H the target's height in pixels; the
 *                       reflection's half-resolution target halves its pixel count, and so its triangles, by itself).
 *                       The sun's pass cuts its casters by the viewer's bound, so that they are the very ground that
 *                       receives their shadows: coarser casters stand above it in every hollow and shadow it there
 *                       (the dark streaks of acne down a sunlit face), finer ones shadow it under every bump
 * @param baseResolution the paper rule's B in L = ⌊log2(D / B)⌋: the distance at which the terrain drops its first
 *                       level of detail. A patch of level L is drawn from B·2^L to B·2^(L+1) away with vertices
 *                       2^L samples apart, so a triangle edge subtends between Δ/(2B) and Δ/B radians at every level
 *                       (Δ the sample spacing), and a full ring of one level holds about 6π(B/Δ)² triangles. The
 *                       default 128 m gives 4–8 pixel edges for 1 m samples at 1080 lines and a 60° view (1030 px
 *                       per radian), about 75 000 visible triangles per level; larger is finer and costlier
 * @param mode           quadtree cut (the default, patch count logarithmic in the world size) or the paper's flat
 *                       grid (for figure 6)
 * @param reflectionCoarsening the paper rule's levels coarser in the water's reflection pass: the reflection is
 *                       drawn at half resolution and seen wobbling on the ripples, so detail finer than its pixels
 *                       cannot be seen; each level halves B there, a quarter of the triangles
 * @param shadowCoarsening the paper rule's levels coarser in the sun's shadow pass, with distances from the viewer's
 *                       eye: a shadow is seen through the map's texels and the PCF filter, which blur detail finer
 *                       than a few texels, and a coarser caster moves its shadow's edge by less than that; each level
 *                       halves B there
 * @param morph          geomorphing: in the quadtree cut, each vertex blends into the next coarser level's surface
 *                       over its patch's transition band, so a level change moves no vertex abruptly
 *                       ({@link QuadtreeLod}); on by default. Off draws each level's own surface (the paper's), as
 *                       the flat grid always does, and a level change then moves vertices by up to the error the
 *                       rule allows
 */
public record LodSettings(
        @Setting(doc = "vertices per patch side (17, 33 or 65)", min = 17, max = 65, atStart = true) int patchVertices,
        @Setting(doc = "when a patch is fine enough: SCREEN_ERROR (its error in pixels) or PAPER (distance, "
                + "figure 6)") LodRule rule,
        @Setting(doc = "screen-error rule: most pixels a patch's height error may cover", unit = "px", min = 0.1,
                max = 100) double pixelError,
        @Setting(doc = "paper rule: base resolution B, distance of the first level drop", unit = "m", min = 1,
                max = 100000) double baseResolution,
        @Setting(doc = "level-of-detail scheme: QUADTREE or FLAT_GRID (the paper's, figure 6)") LodMode mode,
        @Setting(doc = "paper rule: levels coarser in the water's reflection pass", min = 0, max = 4)
        int reflectionCoarsening,
        @Setting(doc = "paper rule: levels coarser in the sun's shadow pass", min = 0, max = 4) int shadowCoarsening,
        @Setting(doc = "geomorphing: vertices blend into the coarser level before a level change") boolean morph) {

    public static final LodSettings DEFAULTS = new LodSettings(33, LodRule.SCREEN_ERROR, 6, 128, LodMode.QUADTREE,
            1, 1, true);

    public static final SettingsGroup<LodSettings> SETTINGS = SettingsGroup.of("lod", LodSettings.class, DEFAULTS);

    public LodSettings {
        if (patchVertices != 17 && patchVertices != 33 && patchVertices != 65) {
            throw new IllegalArgumentException("patch vertices must be 17, 33 or 65, got " + patchVertices);
        }
        if (!(pixelError > 0)) {
            throw new IllegalArgumentException("pixel error must be positive, got " + pixelError);
        }
        if (!(baseResolution > 0)) {
            throw new IllegalArgumentException("base resolution must be positive, got " + baseResolution);
        }
        if (rule == null || mode == null) {
            throw new IllegalArgumentException("level-of-detail rule or mode missing");
        }
    }

    /**
     * How fine the terrain must be in a pass drawn with a camera into a target of width × height pixels: by the
     * paper's rule B of {@link #baseResolution(Pass)}; by the screen-error rule {@link #pixelError()} pixels. Under
     * the screen-error rule the sun's pass takes the viewer's limit, not its own box's: its casters are the ground
     * the viewer sees ({@link org.openworld.engine.terrain.TerrainSystem}).
     */
    public DetailLimit limit(Pass pass, ViewCamera camera, int width, int height) {
        return switch (rule) {
            case PAPER -> DetailLimit.paper(baseResolution(pass));
            case SCREEN_ERROR -> DetailLimit.projected(camera.projection(), width, height, pixelError);
        };
    }

    /** The paper rule's B in a pass: coarser by {@link #reflectionCoarsening()} levels in the water's reflection,
     *  by {@link #shadowCoarsening()} in the sun's shadow pass. */
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

package org.openworld.engine.shadow;

import org.openworld.engine.gl.Format;
import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Settings of the sun's shadows, keys {@code shadow.*}.
 *
 * @param method       CASCADES (the default: several maps, each fitted to a slice of the view, stable under camera
 *                     motion) or PAPER (section 3.2: one map over everything the camera sees, refitted every frame,
 *                     with the margin as its only bias; for figures 10–12)
 * @param resolution   texels per side of each map
 * @param margin       the paper's Z-buffer margin, in depth-buffer units (0 .. 1 over the light box's depth): a point
 *                     is shadowed only when something is nearer the sun by more than this. Figure 10's series is 0,
 *                     0.001, 0.01, 0.1; figure 12 uses 0.01. Added to the cascades' own biases too
 * @param depth        how the maps store depth: FLOAT32 (the default, 32-bit float) or FIXED24 (the paper's 24-bit
 *                     depth buffer: 2^24 equal steps over the box's depth). Both are 0 .. 1 over the box's depth, so
 *                     a margin means the same share of it in both; a float's step is never coarser than 24-bit's
 * @param kernel       side N of the percentage-closer filter: N × N depth tests a texel apart, averaged; odd. Figure
 *                     11's series is 1, 3, 5, 7
 * @param penumbra     CASCADES: where the caster lies so far above the ground that the sun's disc blurs the edge
 *                     wider than the filter, its tests spread to two texels apart (shaders/common/shadow.glsl)
 * @param cascades     maps of the CASCADES method, 1–4, each covering a farther slice of the view
 * @param splitBlend   where the slices are cut, between uniform (0: equal lengths) and logarithmic (1: equal ratios,
 *                     the same texels per pixel in every cascade); the practical scheme of Zhang et al.
 * @param distance     how far from the viewer shadows reach, metres; the last cascade ends here and shadows fade out
 *                     over its last tenth (the PAPER map covers the view up to here)
 * @param normalOffset CASCADES: the looked-up point is moved off the surface along its normal by this many texels
 *                     times the sine of the sun's angle to the normal
 * @param slopeBias    CASCADES: the slope-scaled depth bias: the depth compared is pulled towards the sun by this
 *                     many texels times the tangent of the sun's angle to the normal (and the filter's reach)
 * @param refresh      when a map is redrawn: ALWAYS (every map every frame), MOVED (only when its box moved by a
 *                     texel or the sun turned by more than {@code refreshAngle}) or STAGGERED (the default: MOVED, and
 *                     cascade i at most every 2^i frames, unless its kept box no longer holds its slice of the view)
 * @param refreshAngle degrees the sun may turn before a map drawn for the old direction is redrawn (MOVED and
 *                     STAGGERED); until then the map and its box keep the old direction
 * @param measure      measure flicker and acne each frame into the counters {@code shadow.flicker} and
 *                     {@code shadow.acne} (costs a read-back of the picture: for quality runs, not for timings)
 */
public record ShadowSettings(
        @Setting(doc = "CASCADES (stable cascaded maps) or PAPER (section 3.2's single map)") Method method,
        @Setting(doc = "texels per side of each shadow map", unit = "texels", min = 64, max = 8192) int resolution,
        @Setting(doc = "the paper's Z-buffer margin, in depth-buffer units (figure 10)", min = 0, max = 1)
        double margin,
        @Setting(doc = "how the maps store depth: FLOAT32 or FIXED24 (the paper's 24-bit depth buffer)") Depth depth,
        @Setting(doc = "side N of the N x N percentage-closer filter, odd (figure 11)", min = 1, max = 9) int kernel,
        @Setting(doc = "CASCADES: softer shadow edges far from their casters (the sun's disc)") boolean penumbra,
        @Setting(doc = "number of cascades of the CASCADES method", min = 1, max = 4) int cascades,
        @Setting(doc = "cascade splits: 0 uniform, 1 logarithmic", min = 0, max = 1) double splitBlend,
        @Setting(doc = "how far from the viewer shadows reach", unit = "m", min = 10, max = 40000) double distance,
        @Setting(doc = "CASCADES: normal offset of the looked-up point", unit = "texels", min = 0, max = 10)
        double normalOffset,
        @Setting(doc = "CASCADES: slope-scaled depth bias", unit = "texels", min = 0, max = 10) double slopeBias,
        @Setting(doc = "maps redrawn ALWAYS, when MOVED, or STAGGERED (far cascades less often)") Refresh refresh,
        @Setting(doc = "the sun's turn before its maps are redrawn (MOVED, STAGGERED)", unit = "deg", min = 0,
                max = 5) double refreshAngle,
        @Setting(doc = "measure flicker and acne into the counters (reads the picture back)") boolean measure) {

    /** How the sun's depth is mapped. */
    public enum Method {
        /** Cascaded maps fitted to slices of the view, snapped to whole texels, with slope and normal biases. */
        CASCADES,
        /** The paper's single map over the whole view, refitted each frame, biased by the margin alone. */
        PAPER
    }

    /** How the maps store depth. */
    public enum Depth {
        /** 32-bit float: finer than 24 bits near the sun (depth 0), as fine near depth 1. */
        FLOAT32(Format.DEPTH32F),
        /** 24-bit fixed point, the paper's depth buffer: steps of 1 / (2^24 − 1) of the box's depth everywhere. */
        FIXED24(Format.DEPTH24);

        /** The texture format of the maps. */
        public final Format format;

        Depth(Format format) {
            this.format = format;
        }
    }

    /** When a map is redrawn; a map not redrawn keeps its depths and its box from the frame that drew it. */
    public enum Refresh {
        /** Every map, every frame. */
        ALWAYS,
        /** A map whose box moved (by whole texels, or the sun turned by more than the refresh angle). */
        MOVED,
        /**
         * As MOVED, but cascade i at most every 2^i frames, at most one of the far cascades a frame, unless its kept
         * box no longer holds its slice of the view.
         */
        STAGGERED
    }

    public static final ShadowSettings DEFAULTS = new ShadowSettings(Method.CASCADES, 2048, 0, Depth.FLOAT32, 3,
            true, 4, 0.75, 8000, 1.0, 1.0, Refresh.STAGGERED, 0.05, false);

    public static final SettingsGroup<ShadowSettings> SETTINGS =
            SettingsGroup.of("shadow", ShadowSettings.class, DEFAULTS);

    public ShadowSettings {
        if (method == null || depth == null || refresh == null) {
            throw new IllegalArgumentException("shadow method, depth and refresh must be given");
        }
        if (kernel % 2 == 0) {
            throw new IllegalArgumentException("the filter kernel must be odd (centred on the point), got " + kernel);
        }
    }

    /** Maps drawn each frame: {@link #cascades} for CASCADES, one for PAPER. */
    public int maps() {
        return method == Method.PAPER ? 1 : cascades;
    }
}

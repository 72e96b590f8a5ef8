package org.openworld.engine.antialias;

import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Settings of the picture's anti-aliasing ({@link Fxaa}, {@link org.openworld.engine.temporal.TemporalAntialias}).
 *
 * @param method   OFF: the scene target is the picture, every edge a staircase; FXAA: one post pass finds the edges
 *                 by their contrast and blends each pixel with its neighbour across the edge by the share of the
 *                 pixel the edge should cover; TAA: each frame drawn a fraction of a pixel off and blended into the
 *                 history of the frames before, reprojected, so that a pixel is the mean of many samples
 * @param subpixel how much a pixel that stands out from all its neighbours (a one-pixel glint, a thin line) is
 *                 blended into them: 0 keeps it, 1 blends it most (FXAA's "subpix"); more is steadier in motion and
 *                 softer
 * @param blend    TAA: the least share of a new frame in the picture, once the history holds 1 / blend frames (before
 *                 that, each frame has an equal share): less averages more frames, steadier and slower to follow a
 *                 change
 * @param samples  TAA: the jitter's offsets in one cycle, the samples a pixel of a settled still picture: more is
 *                 a finer mean, and a still picture takes that many frames to settle; with a blend
 *                 of 1 / samples a settled picture is the exact mean of one cycle
 */
public record AntialiasSettings(
        @Setting(doc = "anti-aliasing of the picture: off, fxaa (a post pass over the scene's edges) or taa (jittered "
                + "frames blended through a reprojected history)")
        Method method,
        @Setting(doc = "FXAA: how much a pixel standing out from all its neighbours is blended into them", min = 0,
                max = 1) double subpixel,
        @Setting(doc = "TAA: the least share of a new frame in the picture (1 / samples: a mean of one jitter cycle)",
                min = 0.004, max = 1) double blend,
        @Setting(doc = "TAA: the jitter's offsets in one cycle, the samples a pixel of a settled still picture",
                unit = "samples", min = 1, max = 256) int samples) {

    /** How the picture is anti-aliased. */
    public enum Method {
        /** None: the scene target is shown as drawn. */
        OFF,
        /** Fast approximate anti-aliasing (Lottes 2009), one full-screen pass after the scene. */
        FXAA,
        /** Temporal anti-aliasing: jittered frames blended through a history reprojected from depth. */
        TAA
    }

    /**
     * TAA; FXAA's own default amount of sub-pixel blending (FXAA 3.11's {@code fxaaQualitySubpix}); a new frame's
     * share at least 1/16: the first 16 frames of a run equally, then an exponential mean over about 31 frames
     * (2 / blend − 1), half a second at 60 frames a second; 32 offsets a cycle, twice the 16 samples a pixel of
     * {@code openworld stability}'s references, so a settled picture's own sampling noise stays below theirs (16
     * offsets shimmered more: docs/benchmarks.md, "Temporal stability").
     */
    public static final AntialiasSettings DEFAULTS = new AntialiasSettings(Method.TAA, 0.75, 0.0625, 32);

    public static final SettingsGroup<AntialiasSettings> GROUP =
            SettingsGroup.of("antialias", AntialiasSettings.class, DEFAULTS);

    /**
     * Frames a still camera needs before the picture is settled: TAA's history holds one frame of each of the
     * jitter's {@code samples} offsets; one for the others. {@code shot} and {@code stability} render this many.
     */
    public int framesToSettle() {
        return method == Method.TAA ? samples : 1;
    }

    /** Whether a pass runs at all. */
    public boolean enabled() {
        return method != Method.OFF;
    }
}

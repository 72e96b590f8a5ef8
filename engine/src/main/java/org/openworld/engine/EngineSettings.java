package org.openworld.engine;

import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Settings of the frame loop itself.
 *
 * @param step        the fixed simulation step: the world advances by exactly this much per update, whatever the
 *                    frame rate, so a camera path replays identically
 * @param maxSteps    updates allowed per rendered frame before the simulation lets real time slip (a slow frame
 *                    must not start a spiral of ever more catch-up updates)
 * @param seed        the world seed: every random choice (terrain, snow, clouds, ripples, particles) derives from
 *                    it, so one seed and one set of settings give the same world on every machine ({@code --seed}
 *                    sets it)
 * @param renderScale the viewer's passes draw at this multiple of the picture's width and height, then one linear
 *                    blit resizes them to the picture ({@link ScaledScene}): below 1 shading is paid on scale² of the
 *                    pixels, at the price of a softer picture; at 2 (the one value above 1) every pixel of the
 *                    picture is the mean of 2 × 2 samples, supersampling at four times the shading; the panel and
 *                    HUD still draw at full size
 */
public record EngineSettings(
        @Setting(doc = "fixed simulation step", unit = "s", min = 0.001, max = 0.1) double step,
        @Setting(doc = "most simulation steps per rendered frame", min = 1, max = 60) int maxSteps,
        @Setting(doc = "world seed", min = 0, max = Integer.MAX_VALUE, atStart = true) int seed,
        @Setting(doc = "viewer's passes drawn at this multiple of the picture's size: 0.25 .. 1, or 2 (2 x 2 "
                + "samples a pixel)", min = 0.25, max = 2)
        double renderScale) {

    /**
     * Above 1 the scale is 2 alone: one linearly filtered blit halving each side samples exactly between four texels,
     * their mean, a box filter over the picture's pixel; at another factor above 1 one bilinear tap would read only
     * part of a pixel's samples (at 1.5, two of them with weights by position), which is no filter.
     */
    public EngineSettings {
        if (renderScale > 1 && renderScale != SUPERSAMPLED) {
            throw new IllegalArgumentException("above 1 the render scale must be " + (int) SUPERSAMPLED
                    + " (2 x 2 samples a pixel, averaged), got " + renderScale);
        }
    }

    /** The one render scale above 1: 2 × 2 samples a pixel. */
    public static final double SUPERSAMPLED = 2;

    public static final EngineSettings DEFAULTS = new EngineSettings(1.0 / 60.0, 8, 1, 1);

    public static final SettingsGroup<EngineSettings> GROUP = SettingsGroup.of("engine", EngineSettings.class, DEFAULTS);
}

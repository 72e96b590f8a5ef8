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
 * @param renderScale the viewer's passes draw at this fraction of the picture's width and height, then one linear
 *                    blit stretches them over the picture ({@link ScaledScene}): shading is paid on scale² of the
 *                    pixels, at the price of a softer picture; the panel and HUD still draw at full size
 */
public record EngineSettings(
        @Setting(doc = "fixed simulation step", unit = "s", min = 0.001, max = 0.1) double step,
        @Setting(doc = "most simulation steps per rendered frame", min = 1, max = 60) int maxSteps,
        @Setting(doc = "world seed", min = 0, max = Integer.MAX_VALUE, atStart = true) int seed,
        @Setting(doc = "viewer's passes drawn at this fraction of the picture's size", min = 0.25, max = 1)
        double renderScale) {

    public static final EngineSettings DEFAULTS = new EngineSettings(1.0 / 60.0, 8, 1, 1);

    public static final SettingsGroup<EngineSettings> GROUP = SettingsGroup.of("engine", EngineSettings.class, DEFAULTS);
}

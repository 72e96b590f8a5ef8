package org.openworld.engine.grass;

import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Settings of the grass near the eye, keys {@code grass.*}.
 *
 * @param density  blades per square metre where the land grows the most grass; drawn in tufts of
 *                 {@link GrassField#BLADES}, one tuft to a cell of the world's grid
 * @param distance how far from the viewer blades are drawn, metres; they thin out into the ground over the last
 *                 {@link GrassField#FADE_SHARE} of it
 * @param height   the tallest blade, metres; a blade is 0.7 to 1.3 times the mean height the land gives it
 * @param maxSlope the steepest ground grass grows on, degrees: the terrain shows rock from 35 degrees
 */
public record GrassSettings(
        @Setting(doc = "blades per square metre where the land grows the most grass", unit = "1/m2", min = 1,
                max = 200) double density,
        @Setting(doc = "distance from the viewer at which the blades end", unit = "m", min = 5, max = 200)
        double distance,
        @Setting(doc = "tallest blade", unit = "m", min = 0.05, max = 2) double height,
        @Setting(doc = "steepest ground grass grows on", unit = "deg", min = 0, max = 80) double maxSlope) {

    public static final GrassSettings DEFAULTS = new GrassSettings(
            24,    // 1/m2: six tufts of four blades; a real meadow has thousands, each of ours stands for a clump
            40,    // m: the blades thin away from 28 m, where the ground's own grass texture carries the meadow on
            0.5,   // m: a grazed mountain meadow's grass
            30);   // deg: the trees' limit, short of the rock that shows from 35 deg (terrain/material.glsl)

    public static final SettingsGroup<GrassSettings> SETTINGS =
            SettingsGroup.of("grass", GrassSettings.class, DEFAULTS);

    /** The steepest ground as the tangent of its angle: rise over run. */
    public double maxGradient() {
        return Math.tan(Math.toRadians(maxSlope));
    }

    /** The side of a tuft's cell, metres: {@link GrassField#BLADES} blades per cell at {@link #density}. */
    public double cell() {
        return Math.sqrt(GrassField.BLADES / density);
    }
}

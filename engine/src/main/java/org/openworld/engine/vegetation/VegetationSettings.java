package org.openworld.engine.vegetation;

import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Settings of the trees and bushes, keys {@code vegetation.*}.
 *
 * @param density      plants per hectare (10 000 m²) where the placement field is full (a forest on moist ground);
 *                     the open gets a few per cent of it, a dry ridge half ({@link PlacementField})
 * @param maxSlope     the steepest ground a plant stands on, degrees: trees hold on slopes a walker can climb, not
 *                     on rock faces
 * @param minHeight    the shortest tree, metres (bushes are a sixth of it, broadleaf trees four fifths)
 * @param maxHeight    the tallest tree, metres; at least {@code minHeight}
 * @param viewDistance how far from the viewer plants are drawn, metres; they shrink into the ground over the last
 *                     fifth of it, in every pass alike
 * @param lodDistance  the distance from the viewer where full shapes give way to simplified ones, metres,
 *                     cross-faded (dithered) over a tenth of this distance either side
 * @param impostorDistance the distance from the viewer where simplified shapes give way to impostors (cards showing
 *                     the plant baked from many directions), metres, cross-faded as the first switch; one nearer
 *                     than {@code lodDistance} counts as that distance (no simplified shapes)
 * @param shoreMargin  how far above the water a plant's foot must be, metres (the wet rim holds none)
 */
public record VegetationSettings(
        @Setting(doc = "plants per hectare where the land grows forest", unit = "1/ha", min = 0, max = 600)
        double density,
        @Setting(doc = "steepest ground a plant stands on", unit = "deg", min = 0, max = 80) double maxSlope,
        @Setting(doc = "shortest tree", unit = "m", min = 1, max = 100) double minHeight,
        @Setting(doc = "tallest tree", unit = "m", min = 1, max = 100) double maxHeight,
        @Setting(doc = "distance from the viewer at which plants end", unit = "m", min = 100, max = 10_000)
        double viewDistance,
        @Setting(doc = "distance from the viewer where full shapes give way to simplified ones", unit = "m",
                min = 10, max = 5000) double lodDistance,
        @Setting(doc = "distance from the viewer where simplified shapes give way to impostors", unit = "m",
                min = 10, max = 5000) double impostorDistance,
        @Setting(doc = "height of a plant's foot above the water, at least", unit = "m", min = 0, max = 100)
        double shoreMargin) {

    public VegetationSettings {
        if (maxHeight < minHeight) {
            throw new IllegalArgumentException("the tallest tree (" + maxHeight + " m) is shorter than the shortest ("
                    + minHeight + " m)");
        }
    }

    public static final VegetationSettings DEFAULTS = new VegetationSettings(
            100,   // 1/ha in the forest: a stand of grown trees, 10 m apart, with the ground seen between them
            30,    // deg: steeper than most meadows, short of the rock that shows from 35 deg (material.glsl)
            8,     // m: a young spruce
            24,    // m: a grown one; mountain spruce rarely exceed 30 m
            1500,  // m: a 16 m tree is then 6 px tall at 1080p, small enough to go unnoticed as it shrinks away
            150,   // m: a 16 m tree is 110 px tall at 1080p there, and the two shapes differ little (TreeRenderTest)
            400,   // m: a 16 m tree is 41 px tall at 1080p there, under the impostors' 64 px frames (ImpostorTest)
            2);    // m: above the lakes' wet rim

    public static final SettingsGroup<VegetationSettings> SETTINGS =
            SettingsGroup.of("vegetation", VegetationSettings.class, DEFAULTS);

    /** The impostors' distance, metres, never nearer than the simplified shapes' (the keys are set one by one). */
    public double impostorFrom() {
        return Math.max(impostorDistance, lodDistance);
    }

    /** The steepest ground as the tangent of its angle: rise over run, what the height field's gradient gives. */
    public double maxGradient() {
        return Math.tan(Math.toRadians(maxSlope));
    }
}

package org.openworld.engine.trees;

import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Settings of the trees, keys {@code trees.*}.
 *
 * @param density      trees per hectare (10 000 m²) where they may grow; the jittered grid's cells are
 *                     {@code 100 / √density} m apart (18 m at the default)
 * @param maxSlope     the steepest ground a tree stands on, degrees: conifers hold on slopes a walker can climb, not
 *                     on rock faces
 * @param minHeight    the shortest tree, metres
 * @param maxHeight    the tallest tree, metres; at least {@code minHeight}
 * @param viewDistance how far from the viewer trees are drawn, metres; they shrink into the ground over the last
 *                     fifth of it, in every pass alike
 * @param shoreMargin  how far above the water a tree's foot must be, metres (the wet shore holds no conifers)
 */
public record TreeSettings(
        @Setting(doc = "trees per hectare where they may grow", unit = "1/ha", min = 0.1, max = 400) double density,
        @Setting(doc = "steepest ground a tree stands on", unit = "deg", min = 0, max = 80) double maxSlope,
        @Setting(doc = "shortest tree", unit = "m", min = 1, max = 100) double minHeight,
        @Setting(doc = "tallest tree", unit = "m", min = 1, max = 100) double maxHeight,
        @Setting(doc = "distance from the viewer at which trees end", unit = "m", min = 100, max = 10_000)
        double viewDistance,
        @Setting(doc = "height of a tree's foot above the water, at least", unit = "m", min = 0, max = 100)
        double shoreMargin) {

    public TreeSettings {
        if (maxHeight < minHeight) {
            throw new IllegalArgumentException("the tallest tree (" + maxHeight + " m) is shorter than the shortest ("
                    + minHeight + " m)");
        }
    }

    public static final TreeSettings DEFAULTS = new TreeSettings(
            30,    // 1/ha: open woodland, the ground seen between the trees (a closed spruce forest has 500 and more)
            30,    // deg: steeper than most meadows, short of the rock that shows from 35 deg (terrain/material.glsl)
            8,     // m: a young spruce
            24,    // m: a grown one; mountain spruce rarely exceed 30 m
            1500,  // m: a 16 m tree is then 6 px tall at 1080p, small enough to go unnoticed as it shrinks away
            2);    // m: above the lakes' wet rim

    public static final SettingsGroup<TreeSettings> SETTINGS = SettingsGroup.of("trees", TreeSettings.class, DEFAULTS);

    /** The steepest ground as the tangent of its angle: rise over run, what the height field's gradient gives. */
    public double maxGradient() {
        return Math.tan(Math.toRadians(maxSlope));
    }
}

package org.openworld.engine.terrain.material;

import org.openworld.engine.environment.SnowLine;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.material.MaterialSettings.SnowMode;

/**
 * The terrain's snow rules as heights in metres, for the world's {@link SnowLine}: what grows or falls on the ground
 * (trees, settling flakes) can ask where snow lies without knowing how the terrain places it.
 *
 * <p>Both rules work on the normalised height n (0 at the lowest sample of the height map, 1 at the highest, as the
 * materials' {@code height01} and the {@link SnowMap}'s n = h / relief + seaFraction; the generated or imported map
 * is normalised so the two agree), turned into metres by {@code h = min + n · (max − min)} over the map's range:
 * <ul>
 *   <li>{@link SnowMode#SNOW_MAP} (figure 1b): from {@code terrain.snow-base} to {@code terrain.snow-full}, where the
 *       snow map's chance rises from 0 to 1;</li>
 *   <li>{@link SnowMode#ALTITUDE_BANDS} (figure 1a): the band {@link #BAND_LINE} ± {@link #BAND_EDGE}, whose
 *       ends {@code shaders/terrain/material/material.glsl} gets from here as {@code uMatSnowBand}.</li>
 * </ul>
 * Limits: the line is the rule's, not every pixel's. The snow map's opening keeps closed snow fields only where the
 * chance is near 1, just under the full line, and leaves a speckled fringe below; snow slides off slopes steeper
 * than 52° at any height; and the materials bend the edges with noise, by a few percent of the relief.
 */
public final class SnowLines {

    /** ALTITUDE_BANDS: normalised height of the snow line, the top 38 % of the relief white (the paper's figure 1a). */
    public static final double BAND_LINE = 0.62;
    /** ALTITUDE_BANDS: half width of the band's transition, normalised (3 m over the default 800 m: a sharp line). */
    public static final double BAND_EDGE = 0.004;

    private SnowLines() {
    }

    /** The snow line of the chosen rule over heights normalised from {@code lowest} (0) to {@code highest} (1). */
    public static SnowLine of(double lowest, double highest, SnowMode mode, TerrainSettings terrain) {
        return switch (mode) {
            case SNOW_MAP -> new SnowLine(metres(lowest, highest, terrain.snowBase()),
                    metres(lowest, highest, terrain.snowFull()));
            case ALTITUDE_BANDS -> new SnowLine(metres(lowest, highest, BAND_LINE - BAND_EDGE),
                    metres(lowest, highest, BAND_LINE + BAND_EDGE));
        };
    }

    /** A normalised height (0 at {@code lowest}, 1 at {@code highest}) in metres. */
    static double metres(double lowest, double highest, double normalised) {
        return lowest + normalised * (highest - lowest);
    }
}

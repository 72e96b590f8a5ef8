package org.openworld.engine.terrain.material;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.openworld.engine.environment.SnowLine;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.heights.TestTerrain;
import org.openworld.engine.terrain.material.MaterialSettings.SnowMode;

/** The snow rules' normalised heights in metres, over height maps whose range is known. */
class SnowLinesTest {
    // Tolerances here: snow lines in metres from normalised heights in double: 1e-3 m is round-off

    /** 800 m of relief, 15 % below sea level; snow from 35 % to 60 % of it. */
    static final TerrainSettings S = TestTerrain.settings("terrain.relief=800", "terrain.sea-fraction=0.15",
            "terrain.snow-base=0.35", "terrain.snow-full=0.6");

    /** A map rising linearly along x from {@code low} to {@code high} metres. */
    static HeightMap ramp(double low, double high) {
        int n = 64;
        float[] h = new float[n * n];
        for (int i = 0; i < h.length; i++) {
            h[i] = (float) (low + (high - low) * (i % n) / (n - 1.0));
        }
        return new HeightMap(n, 2, h, true);
    }

    /** The map the settings make: from −0.15 · 800 m to 0.85 · 800 m. */
    static final HeightMap NORMALISED = ramp(-S.seaFraction() * S.relief(), (1 - S.seaFraction()) * S.relief());

    @Test
    void theSnowMapsLineIsItsNormalisedHeightsInMetres() {
        SnowLine line = SnowLines.of(NORMALISED.min(), NORMALISED.max(), SnowMode.SNOW_MAP, S);
        // 35 % and 60 % of the way up from the lowest sample, −120 m
        assertEquals(-120 + 0.35 * 800, line.start(), 1e-3);
        // 1e-3 m: metres from normalised heights in double, exact to round-off
        assertEquals(-120 + 0.60 * 800, line.full(), 1e-3);
        // and the snow map's own rule, n = h / relief + seaFraction, gives the same chance at every height
        for (double y = -120; y <= 680; y += 10) {
            assertEquals(SnowMap.probability(y / S.relief() + S.seaFraction(), S), line.chanceAt(y), 1e-6,
                    "the chance of snow at " + y + " m");
        }
    }

    @Test
    void theAltitudeBandsLineIsTheNarrowBandTheMaterialsDraw() {
        SnowLine line = SnowLines.of(NORMALISED.min(), NORMALISED.max(), SnowMode.ALTITUDE_BANDS, S);
        assertEquals(-120 + SnowLines.BAND_LINE * 800, (line.start() + line.full()) / 2, 1e-3);
        assertEquals(2 * SnowLines.BAND_EDGE * 800, line.full() - line.start(), 1e-3);
        // 1 % of the 800 m relief (8 m): the bands' edge is 2 × BAND_EDGE of it; the snow map's fringe spans its base-
        // to-full 25 % or more
        assertTrue(line.full() - line.start() < 0.01 * 800, "a sharp line, not the snow map's wide fringe");
    }

    @Test
    void metresFollowTheMapsOwnRangeWhereverItLies() {
        // a plateau from 1000 to 1400 m: its normalised 0.5 is 1200 m, whatever the settings' relief says
        HeightMap plateau = ramp(1000, 1400);
        assertEquals(1200, SnowLines.metres(plateau.min(), plateau.max(), 0.5), 1e-3);
        SnowLine line = SnowLines.of(plateau.min(), plateau.max(), SnowMode.SNOW_MAP, S);
        assertEquals(1000 + 0.35 * 400, line.start(), 1e-3);
        assertEquals(1000 + 0.60 * 400, line.full(), 1e-3);
    }
}

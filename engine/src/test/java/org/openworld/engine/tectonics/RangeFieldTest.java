package org.openworld.engine.tectonics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.openworld.engine.terrain.heights.BandedHeights;
import org.openworld.engine.terrain.heights.TerrainSettings;

class RangeFieldTest {

    private static TerrainSettings withRanges() {
        TerrainSettings d = TerrainSettings.DEFAULTS;
        return new TerrainSettings(d.size(), d.spacing(), d.relief(), d.seaFraction(), d.beta(), d.minWavelength(),
                d.maxWavelength(), "", d.snowBase(), d.snowFull(), d.snowMorphology(), d.world(), d.memoryBudget(),
                d.importScale(), d.seaLevel(), d.importDetail(), d.erosion(), d.erosionTalus(), true);
    }

    /**
     * Over 400 km × 400 km both plains (the smallest amplitude) and ranges (the whole relief) occur, and the field
     * is smooth at the bands' scale: over the longest band wavelength (2 km), an eighth of the fine lattice's 16 km,
     * the amplitude changes on average by less than a quarter of its span (a change that large would put a range's
     * edge inside a single hillside).
     */
    @Test
    void plainsAndRangesBothOccurAndChangeSlowly() {
        RangeField field = new RangeField(1, 800);
        SplittableRandom random = new SplittableRandom(3);
        double low = 1;
        double high = 0;
        double change = 0;
        int samples = 20_000;
        for (int i = 0; i < samples; i++) {
            double x = (random.nextDouble() - 0.5) * 400_000;
            double z = (random.nextDouble() - 0.5) * 400_000;
            double a = field.amplitude(x, z);
            low = Math.min(low, a);
            high = Math.max(high, a);
            change += Math.abs(field.amplitude(x + 2000, z) - a);
        }
        // doubles: 1e-9 for round-off at the clamped ends
        assertTrue(low <= RangeField.PLAIN_RELIEF + 1e-9, "plains: " + low);
        assertTrue(high >= 1 - 1e-9, "ranges: " + high);
        // ranges are tens of km wide: over 2 km the amplitude changes by a small share of its span; a quarter is the
        // bound chosen, not derived
        assertTrue(change / samples < 0.25 * (1 - RangeField.PLAIN_RELIEF), "mean change over 2 km "
                + change / samples);
    }

    /**
     * The world with ranges keeps its promises: every height within {@code lowest() .. highest()}, and a window made
     * as two halves, the second first, is the same bits as the whole (a block's heights do not depend on what was
     * made before it).
     */
    @Test
    void heightsStayInBoundsAndWindowsAgreeWhateverTheOrder() {
        BandedHeights world = new BandedHeights(withRanges(), 1);
        int n = 64;
        long x0 = 12_000;
        long z0 = -3_000;
        float[] east = world.level(3, x0 + n / 2, z0, n / 2);
        float[] west = world.level(3, x0, z0, n / 2);
        float[] whole = world.level(3, x0, z0, n);
        for (int j = 0; j < n / 2; j++) {
            assertArrayEquals(Arrays.copyOfRange(west, j * n / 2, (j + 1) * n / 2),
                    Arrays.copyOfRange(whole, j * n, j * n + n / 2), "west half, row " + j);
            assertArrayEquals(Arrays.copyOfRange(east, j * n / 2, (j + 1) * n / 2),
                    Arrays.copyOfRange(whole, j * n + n / 2, (j + 1) * n), "east half, row " + j);
        }
        SplittableRandom random = new SplittableRandom(9);
        for (int i = 0; i < 5_000; i++) {
            double h = world.heightAt((random.nextDouble() - 0.5) * 200_000, (random.nextDouble() - 0.5) * 200_000);
            assertTrue(h >= world.lowest() && h <= world.highest(), "height " + h);
        }
    }
}

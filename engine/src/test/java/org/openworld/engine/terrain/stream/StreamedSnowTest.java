package org.openworld.engine.terrain.stream;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.openworld.engine.terrain.heights.BandedHeights;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.heights.TestTerrain;

/** The unbounded world's snow, block by block: seamless, its coarse levels the mean of its finest. */
class StreamedSnowTest {

    private static final TerrainSettings S = TestTerrain.settings();
    private static final BandedHeights WORLD = new BandedHeights(S, 4);
    private static final StreamedSnow SNOW = new StreamedSnow(S, 4);
    private static final int BORDER = StreamedSnow.border(S);

    /** The block of level {@code level} at (ix0, iz0), made from the world's heights with its border. */
    private static byte[] block(int level, long ix0, long iz0, int n) {
        return SNOW.block(level, ix0, iz0, n, WORLD.level(level, ix0 - BORDER, iz0 - BORDER, n + 2 * BORDER),
                BORDER);
    }

    /**
     * A sample's snow is its place's: a 32² block and a 64² block that contains it at an offset agree on every
     * sample they share, so blocks made in any order and at any window position join without a seam (the random
     * draw, the opening and closing and the blur all reach no further than the border).
     */
    @Test
    void blocksJoinWithoutASeam() {
        long x0 = 0;
        long z0 = 20_600;
        while (distinctValues(block(0, x0, z0, 32)) < 50) { // walk east to a snow line
            x0 += 256;
            assertTrue(x0 < 1_000_000, "no snow line found");
        }
        byte[] small = block(0, x0, z0, 32);
        byte[] large = block(0, x0 - 17, z0 - 9, 64);
        for (int j = 0; j < 32; j++) {
            for (int i = 0; i < 32; i++) {
                assertEquals(small[j * 32 + i], large[(j + 9) * 64 + i + 17], "sample " + i + ", " + j);
            }
        }
    }

    private static int distinctValues(byte[] snow) {
        java.util.Set<Byte> values = new java.util.HashSet<>();
        for (byte b : snow) {
            values.add(b);
        }
        return values.size();
    }

    /**
     * c(p), the share the opening and closing leave of a field of chance p: none of nothing, all of everything, and
     * far less than p in between (a lone sample of snow does not survive the opening), rising with p.
     */
    @Test
    void theOpeningKeepsOnlyWhatFillsItsSquare() {
        // doubles: the end points are exact, equal to round-off
        assertEquals(0, SNOW.expectedCoverage(0), 1e-9);
        assertEquals(1, SNOW.expectedCoverage(1), 1e-9);
        // at p = ½ a square of 5 × 5 samples is all snow with chance 2^-25: an opening keeps almost nothing; 0.1 says
        // "far less than p"
        assertTrue(SNOW.expectedCoverage(0.5) < 0.1, "c(0.5) = " + SNOW.expectedCoverage(0.5));
        for (int k = 1; k <= StreamedSnow.TABLE_STEPS; k++) {
            double p = (double) k / StreamedSnow.TABLE_STEPS;
            double q = (double) (k - 1) / StreamedSnow.TABLE_STEPS;
            assertTrue(SNOW.expectedCoverage(p) >= SNOW.expectedCoverage(q), "c rises at p = " + p);
        }
    }

    /**
     * A coarser level shows what level 0's snow averages to: over 1 km² of snowy ground, the mean of level 2's
     * expected coverage and the mean of level 0's random, opened, closed and blurred snow agree within 0.03 (of a
     * mean between 0.1 and 0.9). Read with p of its own smoother height, the coarse level misses the rugged
     * peaks' extremes, and the random draw has its own luck.
     */
    @Test
    void aCoarserLevelShowsTheMeanOfTheFinest() {
        long x0 = 40_960;
        long z0 = 20_480;
        int n = 512; // level-0 samples a side: 1 km
        double fine = mean(block(0, x0, z0, n));
        double coarse = mean(block(2, x0 >> 2, z0 >> 2, n >> 2));
        // see the Javadoc: a mean away from 0 and 1, where agreement would be trivial; 0.03 for the random draw's luck
        // and the coarse level's smoother heights
        assertTrue(fine > 0.1 && fine < 0.9, "snowy ground: " + fine);
        assertEquals(fine, coarse, 0.03, "mean snow of level 0 against level 2 over the same ground");
    }

    /** Level 0 refuses a border its filters would run past. */
    @Test
    void levelZeroNeedsItsBorder() {
        float[] heights = WORLD.level(0, -1, -1, 10);
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> SNOW.block(0, 0, 0, 8, heights, 1));
        assertTrue(e.getMessage().contains("border of " + BORDER), e.getMessage());
        assertArrayEquals(new byte[64], SNOW.block(3, 0, 0, 8, new float[100], 1), "sea-level ground has no snow");
    }

    private static double mean(byte[] snow) {
        double sum = 0;
        for (byte b : snow) {
            sum += (b & 0xFF) / 255.0;
        }
        return sum / snow.length;
    }
}

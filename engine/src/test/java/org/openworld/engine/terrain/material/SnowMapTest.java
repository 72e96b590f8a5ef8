package org.openworld.engine.terrain.material;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.HeightPyramid;
import org.openworld.engine.terrain.heights.SpectralSynthesis;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.heights.TestTerrain;

/** The probabilistic snow map: probability by height, the morphology, the size cap and lookups. */
class SnowMapTest {

    @Test
    void probabilityRisesLinearlyFromBaseToFull() {
        TerrainSettings s = TestTerrain.settings("terrain.snow-base=0.5", "terrain.snow-full=0.9");
        assertEquals(0, SnowMap.probability(0.2, s));
        assertEquals(0, SnowMap.probability(0.5, s));
        // doubles: exact fractions, equal to round-off
        assertEquals(0.5, SnowMap.probability(0.7, s), 1e-12);
        assertEquals(1, SnowMap.probability(0.9, s));
        assertEquals(1, SnowMap.probability(1.0, s));
    }

    /** A periodic map whose normalised height rises linearly along x from 0 to 1 (heights as synthesis makes them). */
    private static HeightPyramid rampPyramid(TerrainSettings s, int n) {
        float[] h = new float[n * n];
        for (int i = 0; i < h.length; i++) {
            double normalised = (i % n) / (n - 1.0);
            h[i] = (float) (s.relief() * (normalised - s.seaFraction()));
        }
        return new HeightPyramid(List.of(new HeightMap(n, 2, h, true)));
    }

    /** Snow fraction of the columns x0 .. x1 − 1. */
    private static double fraction(SnowMap snow, int x0, int x1) {
        int count = 0;
        for (int z = 0; z < snow.size(); z++) {
            for (int x = x0; x < x1; x++) {
                count += snow.snowAt(x, z) ? 1 : 0;
            }
        }
        return count / (double) ((x1 - x0) * snow.size());
    }

    @Test
    void withoutMorphologyEachHeightBandIsSnowWithItsProbability() {
        TerrainSettings s = TestTerrain.settings("terrain.snow-base=0.25", "terrain.snow-full=0.75",
                "terrain.snow-morphology=0");
        int n = 512;
        SnowMap snow = SnowMap.generate(rampPyramid(s, n), s, 9);
        double previous = -1;
        for (int band = 0; band < 8; band++) {
            int x0 = band * n / 8;
            int x1 = (band + 1) * n / 8;
            double expected = 0;
            for (int x = x0; x < x1; x++) {
                expected += SnowMap.probability(x / (n - 1.0), s);
            }
            expected /= x1 - x0;
            double measured = fraction(snow, x0, x1);
            // a band is 64 × 512 = 32 768 Bernoulli samples: the share's σ ≤ 0.5/√32 768 ≈ 0.003, so 0.02 is about 7σ
            assertEquals(expected, measured, 0.02, "band " + band);
            assertTrue(measured >= previous, "snow rises with height");
            previous = measured;
        }
        assertEquals(0, fraction(snow, 0, n / 4), "no snow below the base");
        assertEquals(1, fraction(snow, 3 * n / 4 + 1, n), "all snow above full");
    }

    @Test
    void openingAndClosingRemoveSpecksAndPinholes() {
        TerrainSettings speckled = TestTerrain.settings("terrain.snow-morphology=0");
        TerrainSettings cleaned = TestTerrain.settings("terrain.snow-morphology=2");
        HeightPyramid p = rampPyramid(speckled, 256);
        // near p = ½ one sample in 16 differs from all four neighbours (2 · ½⁵), and the fringe holds thousands of
        // samples: 100 only shows there are many
        assertTrue(isolated(SnowMap.generate(p, speckled, 4)) > 100, "random snow has isolated samples");
        SnowMap clean = SnowMap.generate(p, cleaned, 4);
        assertEquals(0, isolated(clean), "no sample differs from all four neighbours after opening and closing");
        // the ramp's base and full lie at a quarter and three quarters: about half is snow; 0.1–0.9 only says the
        // morphology kept a line
        assertTrue(clean.fraction() > 0.1 && clean.fraction() < 0.9,
                "the snow line is still there: " + clean.fraction());
    }

    /** Samples whose four neighbours all differ from them: single flakes and single pinholes. */
    private static int isolated(SnowMap snow) {
        int count = 0;
        for (int z = 0; z < snow.size(); z++) {
            for (int x = 0; x < snow.size(); x++) {
                boolean v = snow.snowAt(x, z);
                if (snow.snowAt(x - 1, z) != v && snow.snowAt(x + 1, z) != v && snow.snowAt(x, z - 1) != v
                        && snow.snowAt(x, z + 1) != v) {
                    count++;
                }
            }
        }
        return count;
    }

    /**
     * One way for every height source: a block cut from a periodic tile's heights with a border of 4r samples, as
     * the unbounded world cuts its blocks ({@code stream.StreamedSnow}), holds exactly what the tile's own map holds
     * there, in the middle of the tile and across its wrap. The opening and closing reach 4r samples, so the border
     * is exactly enough: the block's filters clamp at its edges, where the tile's wrap, and the two differ only
     * in the border.
     */
    @Test
    void aBlockWithItsBorderHoldsWhatTheTileHolds() {
        TerrainSettings s = TestTerrain.settings("terrain.size=256");
        HeightMap map = SpectralSynthesis.generate(s, 5);
        int n = map.size();
        SnowMap tile = SnowMap.generate(HeightPyramid.build(map), s, 5);
        assertTrue(tile.fraction() > 0.01 && tile.fraction() < 0.99, "a snow line to compare: " + tile.fraction());
        int border = 4 * s.snowMorphology();
        int block = 48;
        int side = block + 2 * border;
        for (int[] at : new int[][] {{100, 60}, {n - 20, n - 30}, {-10, 5}}) {
            float[] heights = new float[side * side];
            for (int j = 0; j < side; j++) {
                for (int i = 0; i < side; i++) {
                    heights[j * side + i] = map.sample(at[0] - border + i, at[1] - border + j);
                }
            }
            byte[] cut = SnowMap.cover(heights, side, at[0] - border, at[1] - border, n, s, 5);
            for (int j = 0; j < block; j++) {
                for (int i = 0; i < block; i++) {
                    assertEquals(tile.snowAt(at[0] + i, at[1] + j), cut[(j + border) * side + i + border] != 0,
                            "sample " + (at[0] + i) + ", " + (at[1] + j) + " of the block at " + at[0] + ", " + at[1]);
                }
            }
        }
    }

    @Test
    void sameSeedSameMapOtherSeedOtherMap() {
        TerrainSettings s = TestTerrain.settings("terrain.size=512");
        HeightPyramid p = HeightPyramid.build(SpectralSynthesis.generate(s, 2));
        byte[] a = SnowMap.generate(p, s, 2).coverage();
        assertArrayEquals(a, SnowMap.generate(p, s, 2).coverage());
        assertTrue(!Arrays.equals(a, SnowMap.generate(p, s, 3).coverage()));
    }

    @Test
    void largeMapsGetASnowMapOfAtMostMaxSize() {
        int n = 2 * SnowMap.MAX_SIZE;
        HeightMap big = new HeightMap(n, 0.5, new float[n * n], true);
        TerrainSettings s = TestTerrain.settings("terrain.snow-morphology=0");
        SnowMap snow = SnowMap.generate(HeightPyramid.build(big), s, 1);
        assertEquals(SnowMap.MAX_SIZE, snow.size());
        assertEquals(1.0, snow.spacing(), "the level's spacing");
    }

    @Test
    void fractionCountsTheSnowSamples() {
        int n = 4;
        byte[] c = new byte[n * n];
        c[2 * n + 2] = SnowMap.SNOW;
        c[3] = SnowMap.SNOW;
        SnowMap snow = new SnowMap(n, 10, false, c);
        assertEquals(2.0 / 16, snow.fraction(), 1e-12);
        assertTrue(snow.snowAt(2, 2) && snow.snowAt(3, 0) && !snow.snowAt(0, 0));
    }
}

package org.openworld.engine.erosion;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.openworld.engine.drainage.DrainageStats;
import org.openworld.engine.drainage.FlowNetwork;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.TerrainData;
import org.openworld.engine.terrain.heights.TerrainSettings;

class ErosionTest {

    /** A small tile: 512² samples 8 m apart (4 km, the default tile's extent), so it is routed at full resolution. */
    private static TerrainSettings small(boolean erosion) {
        TerrainSettings d = TerrainSettings.DEFAULTS;
        return new TerrainSettings(512, 8, d.relief(), d.seaFraction(), d.beta(), 16, d.maxWavelength(), "",
                d.snowBase(), d.snowFull(), d.snowMorphology(), TerrainSettings.World.TILE, d.memoryBudget(),
                d.importScale(), d.seaLevel(), d.importDetail(), erosion, d.erosionTalus(), false);
    }

    private static DrainageStats measure(HeightMap map) {
        int n = map.size();
        boolean[] sea = new boolean[n * n];
        for (int i = 0; i < sea.length; i++) {
            sea[i] = map.heights()[i] <= 0;
        }
        FlowNetwork net = FlowNetwork.open(map.heights(), n, n, map.spacing(), map.spacing(), sea);
        return DrainageStats.of(net, map.heights(), 1e5, 1e7);
    }

    /**
     * Spectral noise has no river network, so its slopes do not fall with drainage area (θ near 0); the eroded tile
     * follows Flint's law in the range real channels show, 0.3–0.6 (see the drainage package).
     */
    @Test
    void erodedTileFollowsFlintsLaw() {
        HeightMap plain = TerrainData.create(small(false), 1, new org.openworld.engine.terrain.heights.StageTimes(s -> { }))
                .pyramid().base();
        HeightMap eroded = TileErosion.erode(plain, TerrainSettings.DEFAULTS.erosionTalus());
        DrainageStats before = measure(plain);
        DrainageStats after = measure(eroded);
        // 0.3: the low end of the real channels' θ range (0.3–0.6, see the drainage package and DrainageStatsTest)
        assertTrue(before.concavity() < 0.3, "plain noise: theta " + before.concavity());
        assertTrue(after.fitted() && after.concavity() > 0.3 && after.concavity() < 0.6,
                "eroded: theta " + after.concavity());
        assertTrue(eroded.periodic(), "a periodic tile stays periodic");
    }

    /** Same map, same bits: the erosion visits cells in a fixed order and its queue breaks ties by cell. */
    @Test
    void erosionIsDeterministic() {
        HeightMap plain = TerrainData.create(small(false), 3, new org.openworld.engine.terrain.heights.StageTimes(s -> { }))
                .pyramid().base();
        float[] a = TileErosion.erode(plain, 38).heights();
        float[] b = TileErosion.erode(plain, 38).heights();
        assertArrayEquals(a, b);
    }

    /**
     * Thermal erosion moves material, never makes or loses it: the sum of the heights is kept up to float rounding.
     * Each pass adds and takes the same float amounts, so the sum changes only by the rounding of each height's
     * addition, at most half an ulp of the largest height per cell and pass: the bound below.
     */
    @Test
    void thermalErosionConservesVolumeAndReachesTheTalus() {
        int n = 64;
        float[] h = new float[n * n];
        SplittableRandom random = new SplittableRandom(5);
        for (int i = 0; i < h.length; i++) {
            h[i] = (float) (random.nextDouble() * 50);
        }
        double before = sum(h);
        double talus = Math.tan(Math.toRadians(38));
        double steepestBefore = steepest(h, n);
        Thermal.relax(h, n, 1, talus, true);
        double rounding = h.length * Thermal.PASSES * 0.5 * Math.ulp(64f);
        assertEquals(before, sum(h), rounding, "volume kept");
        assertTrue(steepest(h, n) < steepestBefore / 2, "slopes above the talus relaxed: " + steepest(h, n));
    }

    private static double sum(float[] h) {
        double s = 0;
        for (float v : h) {
            s += v;
        }
        return s;
    }

    private static double steepest(float[] h, int n) {
        double m = 0;
        for (int z = 0; z < n; z++) {
            for (int x = 0; x < n; x++) {
                m = Math.max(m, Math.abs(h[z * n + x] - h[z * n + (x + 1) % n]));
            }
        }
        return m;
    }
}

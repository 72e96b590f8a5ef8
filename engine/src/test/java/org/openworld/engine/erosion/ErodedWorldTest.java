package org.openworld.engine.erosion;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.openworld.engine.drainage.DrainageStats;
import org.openworld.engine.drainage.FlowNetwork;
import org.openworld.engine.terrain.heights.BandedHeights;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.heights.TestTerrain;

class ErodedWorldTest {

    private static final TerrainSettings ERODED = TestTerrain.settings("terrain.erosion=on");
    private static final BandedHeights BANDS = new BandedHeights(ERODED, 1);
    /** Samples a streamed block has a side, and the border it is made with (as the clipmap makes them). */
    private static final int BLOCK = 64;
    private static final int BORDER = 6;

    private static ErodedWorld fresh() {
        return new ErodedWorld(BANDS, ERODED);
    }

    /** A block of a level with its border, as the clipmap asks for it. */
    private static float[] block(ErodedWorld world, int level, long bx, long bz) {
        return world.level(level, bx * BLOCK - BORDER, bz * BLOCK - BORDER, BLOCK + 2 * BORDER);
    }

    /**
     * Two neighbouring blocks made in either order, each by a world with nothing made yet, are the same to the bit,
     * and the samples they share (the border of one over the other) agree: a height is a function of its place,
     * not of what was made before it. Level 0 reads the routing level between its samples, level 2 is the routing
     * level, level 4 is eroded with the cascade from its coarser levels. Blocks 1 and 2 lie either side of the line
     * between two regions' cores (128 samples a side), where both regions weigh.
     */
    @Test
    void blocksMadeInEitherOrderAgreeToTheBitAtTheirSeam() {
        int[] levels = {0, 2, 4};
        float[][] left = new float[levels.length][];
        float[][] right = new float[levels.length][];
        ErodedWorld first = fresh(); // finest level first, left block first
        for (int k = 0; k < levels.length; k++) {
            left[k] = block(first, levels[k], 1, -2);
            right[k] = block(first, levels[k], 2, -2);
        }
        ErodedWorld second = fresh(); // coarsest level first, right block first
        for (int k = levels.length - 1; k >= 0; k--) {
            assertArrayEquals(right[k], block(second, levels[k], 2, -2), "level " + levels[k] + ", right block");
            assertArrayEquals(left[k], block(second, levels[k], 1, -2), "level " + levels[k] + ", left block");
        }
        int side = BLOCK + 2 * BORDER;
        for (int k = 0; k < levels.length; k++) {
            for (int j = 0; j < side; j++) {
                for (int i = 0; i < 2 * BORDER; i++) { // the left block's last 2·border columns are the right's first
                    assertEquals(left[k][j * side + BLOCK + i], right[k][j * side + i], 0f,
                            "level " + levels[k] + " row " + j);
                }
            }
        }
    }

    /** A height asked for at a sample's place is that sample of a window, to the bit (walking and drawing agree). */
    @Test
    void aHeightAtASampleIsTheWindowsSample() {
        ErodedWorld world = fresh();
        for (int level : new int[] {0, 3}) {
            float[] w = world.level(level, 100, -40, 8);
            double d = world.spacing(level);
            for (int j = 0; j < 8; j++) {
                for (int i = 0; i < 8; i++) {
                    assertEquals(w[j * 8 + i], (float) world.height(level, (100 + i) * d, (-40 + j) * d), 0f);
                }
            }
        }
    }

    /**
     * The eroded world's rivers follow Flint's law where the plain bands' do not: on a 4 km window of the routing
     * level (512² samples 8 m apart, as the tile's test) θ falls in real channels' 0.3–0.6 (the drainage package), and every height stays
     * within the world's stated bounds, which the level choice's boxes rely on.
     */
    @Test
    void theErodedWorldFollowsFlintsLawWithinItsBounds() {
        ErodedWorld world = fresh();
        int n = 512;
        int level = world.routingLevel();
        float[] eroded = world.level(level, -n / 2, -n / 2, n);
        float[] plain = BANDS.level(level, -n / 2, -n / 2, n);
        DrainageStats before = measure(plain, n, world.spacing(level));
        DrainageStats after = measure(eroded, n, world.spacing(level));
        // 0.3 and 0.6: the real channels' range (see the drainage package and DrainageStatsTest)
        assertTrue(before.concavity() < 0.3, "plain bands: theta " + before.concavity());
        assertTrue(after.fitted() && after.concavity() > 0.3 && after.concavity() < 0.6,
                "eroded: theta " + after.concavity());
        for (float h : eroded) {
            assertTrue(h >= world.lowest() && h <= world.highest(), h + " m outside the bounds");
        }
    }

    /**
     * The regions kept stay bounded however far the world is asked about: a walk of 16 blocks east on level 6
     * (128 km) holds no more than the caches allow.
     */
    @Test
    void regionsHeldStayBounded() {
        ErodedWorld world = fresh();
        for (int bx = 0; bx < 16; bx++) {
            block(world, 6, bx, 0);
        }
        assertTrue(world.regionsHeld() <= ErodedWorld.CACHED * world.levels(), world.regionsHeld() + " regions");
    }

    /**
     * The eroded levels' errors, measured near the origin, hold at other places there: the drawn triangles of level
     * L lie within them of the finest eroded heights at 1 000 fresh places within the same span.
     */
    @Test
    void levelErrorsHoldOnErodedHeights() {
        ErodedWorld world = fresh();
        int count = 6;
        float[] errors = world.levelErrors(count);
        SplittableRandom random = new SplittableRandom(7);
        double half = ErodedWorld.ERROR_SPAN_M / 2;
        for (int level = 1; level < count; level++) {
            double worst = 0;
            for (int i = 0; i < 1_000; i++) {
                double x = random.nextDouble(-half, half);
                double z = random.nextDouble(-half, half);
                worst = Math.max(worst, Math.abs(world.heightAt(x, z) - world.surface(level, x, z)));
            }
            assertTrue(worst <= errors[level], "level " + level + ": " + worst + " m seen, " + errors[level]);
        }
    }

    private static DrainageStats measure(float[] h, int n, double spacing) {
        boolean[] sea = new boolean[n * n];
        for (int i = 0; i < sea.length; i++) {
            sea[i] = h[i] <= 0;
        }
        return DrainageStats.of(FlowNetwork.open(h, n, n, spacing, spacing, sea), h, 1e5, 1e7);
    }
}

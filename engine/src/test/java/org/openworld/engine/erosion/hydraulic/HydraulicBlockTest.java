package org.openworld.engine.erosion.hydraulic;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** One block of an unbounded world eroded with its apron: deterministic, and closer to the whole with a wider apron. */
class HydraulicBlockTest {

    private static final int BLOCK = 32;
    private static final double SPACING = PipeErosionTest.SPACING;
    private static final int STEPS = PipeErosionTest.STEPS;

    /** Unbounded hills: heights at any sample, so a block and its apron come from the same source as the whole. */
    private static float height(int x, int z) {
        double a = 2 * Math.PI * x / 40;
        double b = 2 * Math.PI * z / 56;
        return (float) (60 + 25 * Math.sin(a) * Math.cos(b) + 12 * Math.sin(0.7 * a + 1.9 * b) + 0.2 * x);
    }

    /** Samples of the square from (x0, z0), {@code m} a side. */
    private static float[] window(int x0, int z0, int m) {
        float[] h = new float[m * m];
        for (int z = 0; z < m; z++) {
            for (int x = 0; x < m; x++) {
                h[z * m + x] = height(x0 + x, z0 + z);
            }
        }
        return h;
    }

    /** The block at the origin, eroded with {@code apron} samples around it. */
    private static float[] block(int apron) {
        return HydraulicErosion.block(window(-apron, -apron, BLOCK + 2 * apron), BLOCK, apron, SPACING, 38, STEPS,
                PipeErosion::simulate).heights().heights();
    }

    @Test
    void sameSamplesSameBits() {
        assertArrayEquals(block(8), block(8));
    }

    /**
     * The border's effect reaches in from the apron's edge and fades: against the block cut from a run over a much
     * larger window (the apron of 64 samples standing in for the unbounded world), the block's outermost samples,
     * where a neighbour's would meet them, move closer as the apron widens.
     */
    @Test
    void widerApronsMeetTheWholeCloser() {
        float[] whole = block(64);
        double narrow = edgeError(block(4), whole);
        double wide = edgeError(block(24), whole);
        assertTrue(wide < narrow, "edge error with an apron of 24: " + wide + " m, of 4: " + narrow + " m");
    }

    /** The largest difference, metres, along the block's four edges. */
    private static double edgeError(float[] a, float[] b) {
        double worst = 0;
        for (int i = 0; i < BLOCK; i++) {
            int[] cells = {i, (BLOCK - 1) * BLOCK + i, i * BLOCK, i * BLOCK + BLOCK - 1};
            for (int c : cells) {
                worst = Math.max(worst, Math.abs(a[c] - b[c]));
            }
        }
        return worst;
    }
}

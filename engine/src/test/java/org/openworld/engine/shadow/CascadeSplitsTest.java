package org.openworld.engine.shadow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** The practical split scheme against its two pure schemes, and its contract: ends, order, errors. */
class CascadeSplitsTest {

    /** Deterministic: every run draws the same inputs. */
    private static final long SEED = 32;
    /** Relative tolerance for double arithmetic on distances (metres): rounding is near 1e-15. */
    private static final double RELATIVE = 1e-12;

    @Test
    void uniformBlendTakesEqualSteps() {
        double[] d = CascadeSplits.distances(2, 802, 8, 0);
        assertEquals(9, d.length);
        for (int i = 1; i < d.length; i++) {
            assertEquals(100, d[i] - d[i - 1], 100 * RELATIVE, "step " + i);
        }
    }

    @Test
    void logarithmicBlendKeepsAConstantRatio() {
        double near = 0.5;
        double far = 1200;
        int count = 4;
        double[] d = CascadeSplits.distances(near, far, count, 1);
        double ratio = Math.pow(far / near, 1.0 / count);
        for (int i = 1; i < d.length; i++) {
            assertEquals(ratio, d[i] / d[i - 1], ratio * RELATIVE, "ratio " + i);
        }
        // 0.5 · 2400^(1/4) = 3.4996 m: 0.01 m covers writing it as 3.5
        assertEquals(3.5, d[1], 0.01, "the first log slice is thin: 0.5 m · 2400^(1/4)");
    }

    @Test
    void halfBlendIsTheMeanOfTheTwoSchemes() {
        Random random = new Random(SEED);
        for (int trial = 0; trial < 200; trial++) {
            double near = 0.05 + 10 * random.nextDouble();
            double far = near * (1.5 + 5000 * random.nextDouble());
            int count = 1 + random.nextInt(8);
            double[] uniform = CascadeSplits.distances(near, far, count, 0);
            double[] logarithmic = CascadeSplits.distances(near, far, count, 1);
            double[] half = CascadeSplits.distances(near, far, count, 0.5);
            for (int i = 0; i <= count; i++) {
                double mean = (uniform[i] + logarithmic[i]) / 2;
                assertEquals(mean, half[i], mean * RELATIVE, "distance " + i + " of trial " + trial);
            }
        }
    }

    @Test
    void endsAreExactAndDistancesStrictlyIncreaseForRandomInputs() {
        Random random = new Random(SEED + 1);
        for (int trial = 0; trial < 1000; trial++) {
            double near = 1e-3 + 50 * random.nextDouble();
            double far = near * (1 + 1e4 * random.nextDouble() * random.nextDouble()) + 1e-3;
            int count = 1 + random.nextInt(16);
            double blend = random.nextDouble();
            double[] d = CascadeSplits.distances(near, far, count, blend);
            String label = "near " + near + ", far " + far + ", count " + count + ", blend " + blend;
            assertEquals(count + 1, d.length, label);
            assertEquals(near, d[0], 0, label);
            assertEquals(far, d[count], 0, label);
            for (int i = 1; i <= count; i++) {
                assertTrue(d[i] > d[i - 1], "d" + i + " = " + d[i] + " after " + d[i - 1] + " for " + label);
            }
        }
    }

    @Test
    void badInputsAreRejectedByName() {
        assertMessage("near", () -> CascadeSplits.distances(0, 100, 4, 0.5));
        assertMessage("near", () -> CascadeSplits.distances(-1, 100, 4, 0.5));
        assertMessage("near", () -> CascadeSplits.distances(Double.NaN, 100, 4, 0.5));
        assertMessage("far", () -> CascadeSplits.distances(10, 10, 4, 0.5));
        assertMessage("far", () -> CascadeSplits.distances(10, 5, 4, 0.5));
        assertMessage("far", () -> CascadeSplits.distances(10, Double.POSITIVE_INFINITY, 4, 0.5));
        assertMessage("count", () -> CascadeSplits.distances(1, 100, 0, 0.5));
        assertMessage("blend", () -> CascadeSplits.distances(1, 100, 4, -0.01));
        assertMessage("blend", () -> CascadeSplits.distances(1, 100, 4, 1.01));
        assertMessage("blend", () -> CascadeSplits.distances(1, 100, 4, Double.NaN));
        assertMessage("too close", () -> CascadeSplits.distances(1, Math.nextUp(1.0), 4, 0.5));
    }

    private static void assertMessage(String expected, Runnable call) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, call::run);
        assertTrue(e.getMessage().contains(expected), "message '" + e.getMessage() + "' names " + expected);
    }
}

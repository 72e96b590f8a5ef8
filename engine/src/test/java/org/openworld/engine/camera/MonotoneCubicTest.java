package org.openworld.engine.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class MonotoneCubicTest {

    private static final double[] KNOTS = {0, 1, 2.5, 3, 4};

    @Test
    void passesThroughKeysAndNeverBeyondThem() {
        double[] values = {350, 370, 350, 250, 89};
        for (int i = 0; i < KNOTS.length - 1; i++) {
            // doubles: the spline passes through its knots, equal to round-off
            assertEquals(values[i], MonotoneCubic.interpolate(KNOTS, values, i, KNOTS[i]), 1e-9);
            assertEquals(values[i + 1], MonotoneCubic.interpolate(KNOTS, values, i, KNOTS[i + 1]), 1e-9);
            double low = Math.min(values[i], values[i + 1]);
            double high = Math.max(values[i], values[i + 1]);
            for (double t = KNOTS[i]; t <= KNOTS[i + 1]; t += 0.001) {
                double v = MonotoneCubic.interpolate(KNOTS, values, i, t);
                assertTrue(v >= low - 1e-9 && v <= high + 1e-9, v + " at t=" + t + " outside its keys");
            }
        }
    }

    @Test
    void reproducesAStraightLine() {
        double[] values = {1, 3, 6, 7, 9}; // 2t + 1
        assertEquals(6, MonotoneCubic.interpolate(KNOTS, values, 1, 2.5), 1e-9);
        assertEquals(4, MonotoneCubic.interpolate(KNOTS, values, 1, 1.5), 1e-9);
    }

    @Test
    void slopeIsContinuousAcrossAKey() {
        double[] values = {0, 10, 40, 45, 80};
        double h = 1e-6;
        double atKey = MonotoneCubic.interpolate(KNOTS, values, 0, 1);
        double left = (atKey - MonotoneCubic.interpolate(KNOTS, values, 0, 1 - h)) / h;
        double right = (MonotoneCubic.interpolate(KNOTS, values, 1, 1 + h) - atKey) / h;
        // finite differences with h = 1e-6: truncation error h · |f''| ~ 1e-5, rounding ε · |f| / h ~ 1e-8; a kink
        // would differ by whole units
        assertEquals(left, right, 1e-3);
    }
}

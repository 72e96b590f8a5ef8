package org.openworld.engine.origin;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.Random;
import org.junit.jupiter.api.Test;

class RenderOriginTest {

    @Test
    void theOriginIsTheMultipleOfTheStepNearestTheEye() {
        RenderOrigin origin = new RenderOrigin(4096);
        assertTrue(origin.follow(10_003_432, -1000), "from the world's origin it moves");
        assertEquals(2442 * 4096.0, origin.x());
        assertEquals(0, origin.z());
        assertFalse(origin.follow(10_003_432 + 1000, -2047), "within half a step of the same place it stays");
        assertTrue(origin.follow(10_003_432, -2049));
        assertEquals(-4096, origin.z());
        // what the GPU then takes: the eye's few metres from the origin, not its ten thousand kilometres
        assertEquals(1000f, origin.relativeX(10_003_432));
    }

    @Test
    void relativePairsAreEachFromTheOrigin() {
        RenderOrigin origin = new RenderOrigin(8192);
        origin.follow(1220 * 8192.0 + 100, -1221 * 8192.0 - 100);
        float[] copies = {(float) (1220 * 8192.0), (float) (-1221 * 8192.0), (float) (1221 * 8192.0), 0};
        float[] relative = origin.relativePairs(copies);
        assertEquals(0f, relative[0]);
        assertEquals(0f, relative[1]);
        assertEquals(8192f, relative[2]);
        assertEquals((float) (1221 * 8192.0), relative[3]);
    }

    @Test
    void reductionIsExactAgainstDecimalArithmetic() {
        Random random = new Random(7);
        double[] periods = {1, 32, 32 * 0.37, 120, 2.7, 10_000};
        for (int i = 0; i < 10_000; i++) {
            double value = (random.nextDouble() - 0.5) * 2 * (1 << 24) * (random.nextBoolean() ? 1 : 1e-3);
            double period = periods[i % periods.length];
            double reduced = RenderOrigin.reduce(value, period);
            assertTrue(reduced >= 0 && reduced < period, value + " mod " + period + " gave " + reduced);
            // the exact remainder of the two doubles, by decimal arithmetic: fmod is exact, so equal to the last bit
            BigDecimal v = new BigDecimal(value);
            BigDecimal p = new BigDecimal(period);
            BigDecimal r = v.remainder(p);
            if (r.signum() < 0) {
                r = r.add(p);
            }
            assertEquals(r.doubleValue(), reduced, Math.ulp(period), value + " mod " + period);
        }
    }

    @Test
    void aBadStepOrPeriodIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> new RenderOrigin(0));
        assertThrows(IllegalArgumentException.class, () -> new RenderOrigin(Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> RenderOrigin.reduce(1, -1));
    }
}

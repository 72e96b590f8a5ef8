package org.openworld.engine.water;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class WaterOpticsTest {

    @Test
    void extinctionIsPureWaterPlusTheClarityTerm() {
        // clarity 10 m: matter adds 0.1/10 absorption and 0.9/10 scattering, 0.1 per metre in all
        WaterOptics optics = WaterOptics.of(10);
        // float components (24-bit mantissa): 1e-6 on values under 1
        assertEquals(0.35 + 0.1, optics.extinction().x, 1e-6);
        assertEquals(0.057 + 0.1, optics.extinction().y, 1e-6);
        assertEquals(0.0145 + 0.1, optics.extinction().z, 1e-6);
    }

    @Test
    void deepWaterIsBlueAndGordonsFormulaHolds() {
        WaterOptics optics = WaterOptics.of(10);
        // blue: a = 0.0145 + 0.01 = 0.0245, bb = 0.0036 + 0.019 * 0.09 = 0.00531, R = 0.33 * 0.00531 / 0.02981
        assertEquals(0.058781, optics.body().z, 1e-5);
        assertTrue(optics.body().z > optics.body().y && optics.body().y > optics.body().x, "blue > green > red");
    }

    @Test
    void fromInsideTheWaterGlowsWithHalfItsScatteringAlbedo() {
        // green, clarity 10 m: b = 0.09 (+ pure water's 0.0017), σ = 0.157; L = 0.5 · 0.0917 / 0.157
        assertEquals(0.29204, WaterOptics.of(10).inside().y, 1e-4);
    }

    @Test
    void murkierWaterHidesMore() {
        assertTrue(WaterOptics.of(2).extinction().y > WaterOptics.of(20).extinction().y);
        assertThrows(IllegalArgumentException.class, () -> WaterOptics.of(0));
    }
}

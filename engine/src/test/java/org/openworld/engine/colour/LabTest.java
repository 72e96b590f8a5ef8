package org.openworld.engine.colour;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** sRGB to CIELAB against the white point and published values of the sRGB primaries (D65). */
class LabTest {

    private static void assertLab(double l, double a, double b, Lab lab, double tolerance) {
        assertEquals(l, lab.l(), tolerance, "L* of " + lab);
        assertEquals(a, lab.a(), tolerance, "a* of " + lab);
        assertEquals(b, lab.b(), tolerance, "b* of " + lab);
    }

    @Test
    void whiteIsTheWhitePointAndBlackIsZero() {
        // the white point is the matrix's own row sums, so white and the greys come out exact to double round-off
        // through a cube root (1e-6 loose, 1e-9 at black)
        assertLab(100, 0, 0, Lab.fromSrgb(255, 255, 255), 1e-6);
        assertLab(0, 0, 0, Lab.fromSrgb(0, 0, 0), 1e-9);
    }

    @Test
    void primariesMatchPublishedValues() {
        // sRGB primaries in L*a*b* (D65), as colour calculators such as Lindbloom's give them
        // 0.002: the published values have 4 decimals and come from calculators whose matrix and white point may differ
        // from ours in the last digits
        assertLab(53.2408, 80.0925, 67.2032, Lab.fromSrgb(255, 0, 0), 0.002);
        assertLab(87.7347, -86.1827, 83.1793, Lab.fromSrgb(0, 255, 0), 0.002);
        assertLab(32.2970, 79.1875, -107.8602, Lab.fromSrgb(0, 0, 255), 0.002);
    }

    @Test
    void greysHaveNoColourAndGetLighterInOrder() {
        double previous = -1;
        for (int v = 0; v < 256; v += 15) {
            Lab grey = Lab.fromSrgb(v, v, v);
            // greys: exact to round-off, as white above
            assertEquals(0, grey.a(), 1e-6, "a* of grey " + v);
            assertEquals(0, grey.b(), 1e-6, "b* of grey " + v);
            assertTrue(grey.l() > previous, "L* rises with the grey level at " + v);
            previous = grey.l();
        }
    }
}

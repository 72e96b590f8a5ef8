package org.openworld.engine.colour;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * CIEDE2000 against the test pairs of Sharma, Wu and Dalal (2005), table 1, which exercise the formula's corners:
 * hue angles either side of 0/360 degrees, near-neutral colours, the blue rotation, large differences.
 */
class DeltaETest {

    /** Pair number in the paper's table, both colours, and the published ΔE00 (four decimals). */
    private static final double[][] SHARMA_PAIRS = {
        {1, 50.0000, 2.6772, -79.7751, 50.0000, 0.0000, -82.7485, 2.0425},
        {2, 50.0000, 3.1571, -77.2803, 50.0000, 0.0000, -82.7485, 2.8615},
        {3, 50.0000, 2.8361, -74.0200, 50.0000, 0.0000, -82.7485, 3.4412},
        {4, 50.0000, -1.3802, -84.2814, 50.0000, 0.0000, -82.7485, 1.0000},
        {7, 50.0000, 0.0000, 0.0000, 50.0000, -1.0000, 2.0000, 2.3669},
        {9, 50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0009, 7.1792},
        {11, 50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0011, 7.2195},
        {13, 50.0000, -0.0010, 2.4900, 50.0000, 0.0009, -2.4900, 4.8045},
        {15, 50.0000, -0.0010, 2.4900, 50.0000, 0.0011, -2.4900, 4.7461},
        {16, 50.0000, 2.5000, 0.0000, 50.0000, 0.0000, -2.5000, 4.3065},
        {17, 50.0000, 2.5000, 0.0000, 73.0000, 25.0000, -18.0000, 27.1492},
        {18, 50.0000, 2.5000, 0.0000, 61.0000, -5.0000, 29.0000, 22.8977},
        {19, 50.0000, 2.5000, 0.0000, 56.0000, -27.0000, -3.0000, 31.9030},
        {20, 50.0000, 2.5000, 0.0000, 58.0000, 24.0000, 15.0000, 19.4535},
        {25, 60.2574, -34.0099, 36.2677, 60.4626, -34.1751, 39.4387, 1.2644},
        {26, 63.0109, -31.0961, -5.8663, 62.8187, -29.7946, -4.0864, 1.2630},
    };

    @Test
    void matchesThePublishedTestPairsBothWays() {
        for (double[] p : SHARMA_PAIRS) {
            Lab first = new Lab(p[1], p[2], p[3]);
            Lab second = new Lab(p[4], p[5], p[6]);
            // Sharma et al. publish ΔE00 to four decimals: 5e-5 is half the last published digit
            assertEquals(p[7], DeltaE.ciede2000(first, second), 5e-5, "pair " + (int) p[0]);
            assertEquals(p[7], DeltaE.ciede2000(second, first), 5e-5, "pair " + (int) p[0] + " reversed");
        }
    }

    @Test
    void equalColoursAreZeroAndBlackToWhiteIsOneHundred() {
        Lab red = Lab.fromSrgb(255, 0, 0);
        assertEquals(0, DeltaE.ciede2000(red, red), 1e-12);
        // Both grey: only lightness differs, and at a mean L* of 50 its weight S_L is 1.
        assertEquals(100, DeltaE.ciede2000(Lab.fromSrgb(0, 0, 0), Lab.fromSrgb(255, 255, 255)), 1e-6);
    }
}

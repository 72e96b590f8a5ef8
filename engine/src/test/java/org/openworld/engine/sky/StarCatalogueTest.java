package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

/** The synthesised stars (no GL): the real sky's counts by magnitude, spread evenly over the sphere. */
class StarCatalogueTest {

    static final StarCatalogue STARS = StarCatalogue.generate(7);

    /** How many stars are brighter than magnitude m, from their light. */
    static long brighterThan(double m) {
        double light = Math.pow(10, -0.4 * (m - MoonPosition.SUN_MAGNITUDE));
        long n = 0;
        for (float e : STARS.irradiance()) {
            n += e > light ? 1 : 0;
        }
        return n;
    }

    @Test
    void countsFollowTheRealSky() {
        // Allen's counts over the whole sky: about 13 stars brighter than 1, 170 than 3, 4800 than 6; the law is a
        // straight line through them, within a third of each
        assertEquals(13, brighterThan(1), 13 / 3.0);
        assertEquals(170, brighterThan(3), 170 / 3.0);
        assertEquals(4800, brighterThan(6), 4800 / 3.0);
        // and, drawn stratified, exactly the law's own count (within the one star of rounding)
        assertEquals(Math.pow(10, StarCatalogue.COUNT_AT_ZERO + StarCatalogue.COUNT_SLOPE * 4), brighterThan(4), 1);
        // the brightest about Sirius's -1.46: within a magnitude
        double brightest = -2.5 * Math.log10(STARS.irradiance()[0]) + MoonPosition.SUN_MAGNITUDE;
        assertEquals(-1.46, brightest, 1);
    }

    @Test
    void starsAreSpreadEvenlyOverTheSphere() {
        int n = STARS.count();
        int north = 0;
        double sumX = 0;
        for (int i = 0; i < n; i++) {
            float x = STARS.directions()[3 * i];
            float y = STARS.directions()[3 * i + 1];
            float z = STARS.directions()[3 * i + 2];
            // float directions: 24-bit mantissa, a unit vector's squared length rounds to a few 1e-7; 1e-5 is far
            // outside that
            assertEquals(1, x * x + y * y + z * z, 1e-5, "unit direction");
            north += z > 0 ? 1 : 0;
            sumX += x;
        }
        // a fair coin per star: the northern count within 4 standard deviations (0.5 sqrt(n)); a uniform x has
        // variance 1/3, so its mean lies within 4 sqrt(1 / (3n))
        assertEquals(n / 2.0, north, 4 * 0.5 * Math.sqrt(n));
        assertEquals(0, sumX / n, 4 * Math.sqrt(1.0 / (3 * n)));
    }

    @Test
    void theSeedPlacesTheStars() {
        assertArrayEquals(STARS.directions(), StarCatalogue.generate(7).directions());
        assertFalse(Arrays.equals(STARS.directions(), StarCatalogue.generate(8).directions()));
        assertArrayEquals(STARS.irradiance(), StarCatalogue.generate(8).irradiance(), "the counts do not depend on it");
        assertTrue(STARS.irradiance()[0] > STARS.irradiance()[STARS.count() - 1], "brightest first");
    }
}

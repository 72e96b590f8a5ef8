package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;

import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class SpectrumTest {
    // Tolerances here: doubles to round-off (1e-9, 1e-12); the CIE tables' 7 places to 1e-6

    @ParameterizedTest
    @ValueSource(ints = {3, 6, 8, 15, 16})
    void aFlatSpectrumIsNeutral(int count) {
        Spectrum spectrum = Spectrum.sampled(count);
        double[] flat = new double[count];
        Arrays.fill(flat, 0.37);
        Vector3d rgb = spectrum.toRgb(flat, new Vector3d());
        // doubles: a flat spectrum through the normalised matching functions gives the same value to round-off (1e-9,
        // 1e-12)
        assertEquals(0.37, rgb.x, 1e-9);
        assertEquals(0.37, rgb.y, 1e-9);
        assertEquals(0.37, rgb.z, 1e-9);
    }

    @Test
    void wavelengthsFollowTheMidpointRule() {
        Spectrum spectrum = Spectrum.sampled(7);
        assertEquals(7, spectrum.count());
        assertEquals(400 + 0.5 * 50, spectrum.wavelengthNm(0), 1e-12);
        assertEquals(750 - 0.5 * 50, spectrum.wavelengthNm(6), 1e-12);
    }

    @Test
    void colourMatchingReadsTheCieTable() {
        // the CIE 1931 tables to 7 places: 1e-6 is a unit of the last place (the 600 nm row is a table point, exact)
        assertArrayEquals(new double[] {0.4334499, 0.9949501, 0.0087500}, Spectrum.colourMatching(550), 1e-6);
        assertArrayEquals(new double[] {1.0622, 0.631, 0.0008}, Spectrum.colourMatching(600), 1e-9);
        // Halfway between 550 and 555 nm is the mean of the two rows.
        double[] between = Spectrum.colourMatching(552.5);
        assertEquals((0.9949501 + 1.0) / 2, between[1], 1e-6);
    }

    @Test
    void spikesHaveTheirHue() {
        Spectrum spectrum = Spectrum.sampled(16);
        Vector3d blue = spectrum.toRgb(spike(spectrum, 450), new Vector3d());
        assertTrue(blue.z > blue.y && blue.z > blue.x, "450 nm should be blue: " + blue);
        Vector3d red = spectrum.toRgb(spike(spectrum, 610), new Vector3d());
        assertTrue(red.x > red.y && red.x > red.z, "610 nm should be red: " + red);
    }

    /** All the energy in the sample nearest to {@code nm}. */
    private static double[] spike(Spectrum spectrum, double nm) {
        double[] s = new double[spectrum.count()];
        int nearest = 0;
        for (int i = 1; i < s.length; i++) {
            if (Math.abs(spectrum.wavelengthNm(i) - nm) < Math.abs(spectrum.wavelengthNm(nearest) - nm)) {
                nearest = i;
            }
        }
        s[nearest] = 1;
        return s;
    }
}

package org.openworld.engine.terrain.heights;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The radially averaged spectrum on maps of known content, independent of the synthesis. */
class PowerSpectrumTest {

    private static final int N = 128;
    private static final double SPACING = 2;

    @Test
    void twoWavesLandInTheirRingsWithTheirPowerRatio() {
        // amplitude 3 at (kx, kz) = (0, 10), ring 10; amplitude 1 at (12, 16), ring 20
        float[] h = new float[N * N];
        for (int z = 0; z < N; z++) {
            for (int x = 0; x < N; x++) {
                h[z * N + x] = (float) (3 * Math.cos(2 * Math.PI * 10 * z / N)
                        + Math.sin(2 * Math.PI * (12 * x + 16 * z) / N + 0.4));
            }
        }
        List<PowerSpectrum.Bin> bins = PowerSpectrum.of(new HeightMap(N, SPACING, h, true)).bins();
        PowerSpectrum.Bin ring10 = bins.get(9);
        PowerSpectrum.Bin ring20 = bins.get(19);
        // doubles: an exact quotient, equal to round-off
        assertEquals(10 / (N * SPACING), ring10.frequency(), 1e-12);
        double total = bins.stream().mapToDouble(PowerSpectrum.Bin::power).sum();
        // 0.1 % left to the float heights' rounding spread over the other rings; the amplitude ratio 3² = 9 holds to
        // 1e-3 for the same reason
        assertTrue(ring10.power() + ring20.power() > 0.999 * total, "all power in the two rings");
        // Each wave puts |A|² n⁴ / 4 into one coefficient of the half plane; a ring's mean divides by its size.
        double ratio = (ring10.power() * ringSize(10)) / (ring20.power() * ringSize(20));
        assertEquals(9, ratio, 1e-3, "power ratio of amplitudes 3 and 1");
    }

    /** Coefficients of the half plane the spectrum sums over whose radius rounds to k. */
    private static int ringSize(int k) {
        int count = 0;
        for (int r = 0; r < N; r++) {
            int kz = r < N / 2 ? r : r - N;
            for (int kx = 0; kx < N / 2; kx++) {
                boolean stored = kx > 0 || (r > 0 && r < N / 2);
                if (stored && Math.round(Math.sqrt(kx * kx + kz * kz)) == k) {
                    count++;
                }
            }
        }
        return count;
    }

    @Test
    void fitRecoversAPowerLawAndUsesOnlyRingsInsideTheBand() {
        // a field whose ring powers follow f^-3 exactly would need a synthesis; instead check the fit on a spectrum
        // of known shape through the public API: white noise has slope 0
        float[] h = new float[N * N];
        java.util.SplittableRandom random = new java.util.SplittableRandom(1);
        for (int i = 0; i < h.length; i++) {
            h[i] = (float) random.nextGaussian();
        }
        PowerSpectrum spectrum = PowerSpectrum.of(new HeightMap(N, SPACING, h, true));
        PowerSpectrum.Fit fit = spectrum.fit(1 / 200.0, 1 / 5.0);
        // each ring's power is a χ² sample of a few dozen coefficients: a log-log fit over 1.6 decades scatters by
        // about 0.05; 0.15 is the band every spectral-slope test here uses
        assertEquals(0, fit.slope(), 0.15, "white noise has a flat spectrum");
        assertThrows(IllegalArgumentException.class, () -> spectrum.fit(1 / 100.0, 1 / 99.0));
    }
}

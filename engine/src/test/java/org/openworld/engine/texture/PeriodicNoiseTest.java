package org.openworld.engine.texture;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.PowerSpectrum;

/**
 * The materials' periodic noise, GL-free: it tiles, it is standardised, its two fields are independent, and its
 * power falls as the band asks.
 */
class PeriodicNoiseTest {

    private static final int N = 128;

    private static double[][] pair(long seed, PeriodicNoise.Spectrum spectrum) {
        return new PeriodicNoise(N).pair(new SplittableRandom(seed), spectrum);
    }

    /** Mean over the rows of |v(a) − 2 v(b) + v(c)|, three columns: the field's bend across b. */
    private static double columnBend(double[] v, int a, int b, int c) {
        double sum = 0;
        for (int y = 0; y < N; y++) {
            sum += Math.abs(v[y * N + a] - 2 * v[y * N + b] + v[y * N + c]);
        }
        return sum / N;
    }

    /** The same along the columns, three rows. */
    private static double rowBend(double[] v, int a, int b, int c) {
        double sum = 0;
        for (int x = 0; x < N; x++) {
            sum += Math.abs(v[a * N + x] - 2 * v[b * N + x] + v[c * N + x]);
        }
        return sum / N;
    }

    /**
     * A smooth field (no wave shorter than 16 texels) bends across the wrap, from the last column into the first and
     * the last row into the first, no more than between interior neighbours: the left column continues the right.
     * A cut through the middle joined to the first column bends far more, so the measure sees a seam.
     */
    @Test
    void theLeftColumnContinuesTheRightAndTheTopRowTheBottom() {
        for (double[] v : pair(1, PeriodicNoise.band(2, 8, 2))) {
            double columns = 0;
            double rows = 0;
            for (int k = 1; k < N - 1; k++) {
                columns += columnBend(v, k - 1, k, k + 1) / (N - 2);
                rows += rowBend(v, k - 1, k, k + 1) / (N - 2);
            }
            // a smooth field's bend varies about its mean: across the wrap it may be twice the mean of the interior and
            // no more; a cut-and-join seam is a step, more than 10× the mean
            assertTrue(columnBend(v, N - 2, N - 1, 0) < 2 * columns, "across the last column");
            assertTrue(columnBend(v, N - 1, 0, 1) < 2 * columns, "across the first column");
            assertTrue(rowBend(v, N - 2, N - 1, 0) < 2 * rows, "across the last row");
            assertTrue(rowBend(v, N - 1, 0, 1) < 2 * rows, "across the first row");
            assertTrue(columnBend(v, N / 2 - 1, 0, 1) > 10 * columns, "a cut-and-join seam is seen");
        }
    }

    @Test
    void bothFieldsHaveMeanZeroVarianceOneAndAreUncorrelated() {
        double[][] p = pair(2, PeriodicNoise.band(4, 64, 1));
        for (double[] v : p) {
            double mean = 0;
            double square = 0;
            for (double x : v) {
                mean += x / v.length;
                square += x * x / v.length;
            }
            // doubles: the field is normalised to mean 0 and variance 1 exactly, so 1e-9 is round-off over 128² sums
            assertEquals(0, mean, 1e-9, "mean");
            assertEquals(1, square, 1e-9, "variance");
        }
        double correlation = 0;
        for (int i = 0; i < N * N; i++) {
            correlation += p[0][i] * p[1][i] / (N * N);
        }
        // two independent fields of 128² texels correlate with σ = 1/128 ≈ 0.008 if white; band-limited fields have
        // fewer independent samples, so 0.05 is some 3–6σ
        assertTrue(Math.abs(correlation) < 0.05, "real and imaginary parts are independent: " + correlation);
    }

    /** Measured with the terrain's own spectrum tool: power ∝ 1/f^β inside the band, the slope −β on a log-log plot. */
    @Test
    void powerFallsAsOneOverFToTheBeta() {
        for (double beta : new double[] {1.0, 2.6}) {
            double[] v = pair(3, PeriodicNoise.band(1, 400, beta))[0];
            float[] h = new float[N * N];
            for (int i = 0; i < h.length; i++) {
                h[i] = (float) v[i];
            }
            PowerSpectrum.Fit fit = PowerSpectrum.of(new HeightMap(N, 1, h, true)).fit(4.0 / N, 40.0 / N);
            // 0.15 on a log-log slope fitted over one decade of a single 128² realisation: each frequency ring's power
            // is a χ² sample, which scatters the fit (the same band as PowerSpectrumTest)
            assertEquals(-beta, fit.slope(), 0.15, "spectral slope for β = " + beta);
        }
    }

    @Test
    void theBandIsZeroFarOutsideItAndAPowerLawInside() {
        PeriodicNoise.Spectrum band = PeriodicNoise.band(8, 64, 2);
        assertEquals(0, band.amplitude(1), "far below the band");
        assertEquals(0, band.amplitude(500 * 500), "far above the band");
        // 16 and 32 cycles sit symmetrically between the edges (16/8 = 64/32), so the edges cancel in the ratio
        assertEquals(2, band.amplitude(16 * 16) / band.amplitude(32 * 32), 1e-12, "amplitude ∝ f^(−β/2)");
    }

    @Test
    void theSameStreamGivesTheSameFields() {
        double[][] a = pair(4, PeriodicNoise.band(2, 50, 2));
        double[][] b = pair(4, PeriodicNoise.band(2, 50, 2));
        double[][] c = pair(5, PeriodicNoise.band(2, 50, 2));
        assertArrayEquals(a[0], b[0]);
        assertArrayEquals(a[1], b[1]);
        // 1e-6: far above round-off, far below unit-variance values; equal fields give 0
        assertTrue(Math.abs(a[0][0] - c[0][0]) + Math.abs(a[1][7] - c[1][7]) > 1e-6, "another stream, other fields");
    }
}

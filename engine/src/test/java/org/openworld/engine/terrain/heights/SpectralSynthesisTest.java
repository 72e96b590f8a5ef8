package org.openworld.engine.terrain.heights;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.visnow.jlargearrays.ConcurrencyUtils;

/** Spectral synthesis: the spectrum it promises, normalisation, determinism and the seamless wrap. */
class SpectralSynthesisTest {

    @ParameterizedTest
    @ValueSource(doubles = {1.0, 1.6, 2.2, 2.8})
    void powerSpectrumFallsWithSlopeMinusTwoBeta(double beta) {
        TerrainSettings s = TestTerrain.settings("terrain.size=256", "terrain.beta=" + beta);
        HeightMap map = SpectralSynthesis.generate(s, 7);
        PowerSpectrum.Fit fit = PowerSpectrum.of(map).fit(s);
        // 0.15: one 256² realisation, each ring's power a χ² sample, scatters the fitted slope (the band
        // PowerSpectrumTest uses for white noise)
        assertEquals(-2 * beta, fit.slope(), 0.15, "fitted log-log slope of the power spectrum");
    }

    @Test
    void wavelengthsOutsideTheCutOffsAreAbsent() {
        // 512 m tile: keep 50 .. 150 m, i.e. rings 3.4 .. 10.2 cycles per tile
        TerrainSettings s = TestTerrain.settings("terrain.size=256", "terrain.min-wavelength=50",
                "terrain.max-wavelength=150");
        PowerSpectrum spectrum = PowerSpectrum.of(SpectralSynthesis.generate(s, 3));
        double inside = 0;
        double outside = 0;
        for (PowerSpectrum.Bin b : spectrum.bins()) {
            double wavelength = 1 / b.frequency();
            if (wavelength > 60 && wavelength < 140) {
                inside = Math.max(inside, b.power());
            } else if (wavelength < 40 || wavelength > 200) {
                outside = Math.max(outside, b.power());
            }
        }
        assertTrue(inside > 0);
        // the synthesis sets the coefficients outside the band to zero: only the float heights' rounding (about 1e-7
        // relative, squared in power far lower) is left, 1e-6 is far above it
        assertTrue(outside < 1e-6 * inside, "power outside the band " + outside + " vs inside " + inside);
    }

    @Test
    void heightsSpanTheReliefWithTheSeaFractionBelowZero() {
        TerrainSettings s = TestTerrain.settings("terrain.size=256", "terrain.spacing=3", "terrain.relief=500",
                "terrain.sea-fraction=0.2");
        HeightMap map = SpectralSynthesis.generate(s, 1);
        assertEquals(256, map.size());
        assertEquals(3, map.spacing());
        assertTrue(map.periodic());
        // float metres (24-bit mantissa, 3e-5 m at 400 m): 1e-3 m
        assertEquals(-100, map.min(), 1e-3);
        assertEquals(400, map.max(), 1e-3);
    }

    @Test
    void sameSeedSameBitsOtherSeedOtherHeights() {
        TerrainSettings s = TestTerrain.settings("terrain.size=512");
        long a = TestTerrain.bitsHash(SpectralSynthesis.generate(s, 42).heights());
        long b = TestTerrain.bitsHash(SpectralSynthesis.generate(s, 42).heights());
        long c = TestTerrain.bitsHash(SpectralSynthesis.generate(s, 43).heights());
        assertEquals(a, b, "same seed and settings must give the same bits");
        assertNotEquals(a, c, "another seed must give another map");
    }

    @Test
    void resultDoesNotDependOnJTransformsThreadCount() {
        // 512² is above JTransforms' threshold for threaded 2D transforms and above our parallel row threshold.
        TerrainSettings s = TestTerrain.settings("terrain.size=512");
        int saved = ConcurrencyUtils.getNumberOfThreads();
        try {
            Long reference = null;
            for (int threads : new int[] {1, 3, 8}) {
                ConcurrencyUtils.setNumberOfThreads(threads);
                long hash = TestTerrain.bitsHash(SpectralSynthesis.generate(s, 5).heights());
                assertEquals(threads, ConcurrencyUtils.getNumberOfThreads(), "the caller's thread count is restored");
                if (reference == null) {
                    reference = hash;
                }
                assertEquals(reference, hash, "heights with " + threads + " JTransforms threads");
            }
        } finally {
            ConcurrencyUtils.setNumberOfThreads(saved);
        }
    }

    @Test
    void theTileWrapsWithoutASeam() {
        TerrainSettings s = TestTerrain.settings("terrain.size=256");
        HeightMap map = SpectralSynthesis.generate(s, 11);
        int n = map.size();
        // Mean squared difference across each column boundary x | x+1 (and each row boundary): on a torus the wrap
        // boundary n−1 | 0 is one boundary like the others, so it must lie within the interior ones' range.
        for (boolean alongX : new boolean[] {true, false}) {
            double lo = Double.POSITIVE_INFINITY;
            double hi = 0;
            for (int b = 0; b < n - 1; b++) {
                double msd = boundary(map, b, alongX);
                lo = Math.min(lo, msd);
                hi = Math.max(hi, msd);
            }
            double wrap = boundary(map, n - 1, alongX);
            assertTrue(wrap >= lo && wrap <= hi, (alongX ? "x" : "z") + " wrap boundary " + wrap
                    + " m² outside the interior range " + lo + " .. " + hi + " m²");
        }
    }

    /** Mean squared height difference between line b and line b + 1 (wrapped), columns or rows. */
    private static double boundary(HeightMap map, int b, boolean alongX) {
        double sum = 0;
        for (int i = 0; i < map.size(); i++) {
            sum += alongX
                    ? square(map.sample(b + 1, i) - map.sample(b, i))
                    : square(map.sample(i, b + 1) - map.sample(i, b));
        }
        return sum / map.size();
    }

    private static double square(double v) {
        return v * v;
    }
}

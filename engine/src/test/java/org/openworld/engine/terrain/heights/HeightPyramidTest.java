package org.openworld.engine.terrain.heights;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The Gaussian pyramid: its shape, and that it low-passes before decimating. */
class HeightPyramidTest {

    private static final int N = 256;

    /** A periodic map of cos(2π k x / N), k cycles across the tile, amplitude 1. */
    private static HeightMap wave(int k) {
        float[] h = new float[N * N];
        for (int z = 0; z < N; z++) {
            for (int x = 0; x < N; x++) {
                h[z * N + x] = (float) Math.cos(2 * Math.PI * k * x / N);
            }
        }
        return new HeightMap(N, 2, h, true);
    }

    private static double amplitude(HeightMap map) {
        return (map.max() - map.min()) / 2.0;
    }

    @Test
    void levelsHalveDownToOneSampleWithDoubledSpacing() {
        HeightPyramid p = HeightPyramid.build(wave(3));
        assertEquals(9, p.levelCount(), "256, 128, ... 1");
        for (int k = 0; k < p.levelCount(); k++) {
            assertEquals(N >> k, p.level(k).size());
            assertEquals(2.0 * (1 << k), p.level(k).spacing());
            assertTrue(p.level(k).periodic());
        }
        assertEquals(1, p.level(8).size());
    }

    @Test
    void waveAboveTheNewNyquistIsFilteredNotAliased() {
        // 100 cycles per 256 samples = 0.39 cycles/sample: above level 1's Nyquist (0.25), below level 0's (0.5)
        HeightMap fine = wave(100);
        float[] decimated = new float[N / 2 * N / 2];
        for (int z = 0; z < N / 2; z++) {
            for (int x = 0; x < N / 2; x++) {
                decimated[z * N / 2 + x] = fine.sample(2 * x, 2 * z);
            }
        }
        double plain = amplitude(new HeightMap(N / 2, 4, decimated, true));
        double filtered = amplitude(HeightPyramid.build(fine).level(1));
        // every other sample of a pure wave keeps its amplitude (1) as an alias, less the samples' phase: over 0.9; the
        // filter's cos⁴ response gives 0.013, under 0.03
        assertTrue(plain > 0.9, "plain decimation keeps the wave as an alias of amplitude " + plain);
        // the binomial response cos⁴(π · 0.39) is 0.013
        assertTrue(filtered < 0.03, "the pyramid attenuates it to " + filtered);
    }

    @Test
    void waveWellBelowTheNewNyquistPasses() {
        // 10 cycles per 256 samples: response cos⁴(π · 10/256) = 0.970
        double filtered = amplitude(HeightPyramid.build(wave(10)).level(1));
        // cos⁴(π · 10/256) = 0.97025: 0.003 covers writing it as 0.970 and the float heights, ten times over
        assertEquals(0.970, filtered, 0.003);
    }

    @Test
    void aConstantMapStaysConstant() {
        float[] h = new float[N * N];
        java.util.Arrays.fill(h, 123.5f);
        for (boolean periodic : new boolean[] {true, false}) {
            HeightPyramid p = HeightPyramid.build(new HeightMap(N, 1, h.clone(), periodic));
            for (int k = 0; k < p.levelCount(); k++) {
                assertEquals(123.5f, p.level(k).min(), "weights sum to one, level " + k);
                assertEquals(123.5f, p.level(k).max(), "weights sum to one, level " + k);
            }
        }
    }

    @Test
    void periodicMapsWrapAndImportedOnesClampAtTheEdges() {
        // a ramp h = x: at x = 0 the periodic filter reaches back to x = 254, 255; the clamped one repeats sample 0
        float[] h = new float[N * N];
        for (int i = 0; i < h.length; i++) {
            h[i] = i % N;
        }
        HeightMap periodic = HeightPyramid.build(new HeightMap(N, 1, h.clone(), true)).level(1);
        HeightMap clamped = HeightPyramid.build(new HeightMap(N, 1, h.clone(), false)).level(1);
        // float heights of a few hundred: 1e-3 is a few float roundings (24-bit mantissa, 3e-5 at 255)
        assertEquals((254 + 4 * 255 + 6 * 0 + 4 * 1 + 2) / 16.0, periodic.sample(0, 5), 1e-3, "wrapped neighbours");
        assertEquals((0 + 4 * 0 + 6 * 0 + 4 * 1 + 2) / 16.0, clamped.sample(0, 5), 1e-3, "clamped neighbours");
        assertEquals(20, clamped.sample(10, 5), 1e-3, "a ramp stays a ramp inside");
        assertFalse(clamped.periodic());
    }
}

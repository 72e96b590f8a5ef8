package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.PowerSpectrum;

/** The 3D-DFT cloud field: periodic in space and time, normalised, with the spectrum its β asks for. */
class CloudFieldTest {

    private static final int N = 64;
    private static final int FRAMES = 16;
    private static final long SEED = 7;

    private static CloudField field;

    @BeforeAll
    static void generate() {
        field = CloudField.generate(N, FRAMES, 2, SEED);
    }

    /** Mean squared difference between frames t and u, over every sample of a frame. */
    private static double frameDifference(CloudField f, int t, int u) {
        double sum = 0;
        int n = f.resolution();
        for (int y = 0; y < n; y++) {
            for (int x = 0; x < n; x++) {
                double d = f.density(x, y, t) - f.density(x, y, u);
                sum += d * d;
            }
        }
        return sum / (n * n);
    }

    /** Mean squared difference between columns x and x', over every row and frame. */
    private static double columnDifference(CloudField f, int x0, int x1) {
        double sum = 0;
        int n = f.resolution();
        for (int t = 0; t < f.frames(); t++) {
            for (int y = 0; y < n; y++) {
                double d = f.density(x0, y, t) - f.density(x1, y, t);
                sum += d * d;
            }
        }
        return sum / (n * f.frames());
    }

    @Test
    void indicesWrapInEveryAxis() {
        assertEquals(field.density(3, 5, 0), field.density(3, 5, FRAMES));
        assertEquals(field.density(3, 5, 2), field.density(3 + N, 5 - N, 2 - FRAMES));
        assertEquals(field.values()[(2 * N + 5) * N + 3], field.density(3, 5, 2));
        assertEquals(N * N * FRAMES, field.values().length);
    }

    @Test
    void theLoopClosesWithoutAJump() {
        double[] steps = new double[FRAMES - 1];
        for (int t = 0; t < FRAMES - 1; t++) {
            steps[t] = frameDifference(field, t, t + 1);
        }
        double meanStep = Arrays.stream(steps).average().orElseThrow();
        double wrapStep = frameDifference(field, FRAMES - 1, 0);
        double acrossLoop = frameDifference(field, 0, FRAMES / 2);

        // Frames are correlated (independent unit-variance fields differ by 2 on average)...
        assertTrue(meanStep < 1.0, "consecutive frames differ by " + meanStep);
        // ...the step from the last frame back to the first is like any other step...
        assertTrue(wrapStep > 0.5 * meanStep && wrapStep < 2 * meanStep, "wrap " + wrapStep + " vs " + meanStep);
        // ...and the field does change over the loop.
        assertTrue(acrossLoop > 2 * meanStep, "half a loop apart " + acrossLoop + " vs step " + meanStep);
    }

    @Test
    void theTileJoinsWithoutASeam() {
        double meanStep = 0;
        for (int x = 0; x < N - 1; x++) {
            meanStep += columnDifference(field, x, x + 1) / (N - 1);
        }
        double wrapStep = columnDifference(field, N - 1, 0);

        assertTrue(meanStep < 1.0, "neighbouring columns differ by " + meanStep);
        assertTrue(wrapStep > 0.5 * meanStep && wrapStep < 2 * meanStep, "edge " + wrapStep + " vs " + meanStep);
    }

    @Test
    void meanIsZeroAndSpreadIsOne() {
        double sum = 0;
        double squares = 0;
        for (float v : field.values()) {
            sum += v;
            squares += v * (double) v;
        }
        int count = field.values().length;
        double mean = sum / count;
        assertEquals(0, mean, 1e-5);
        assertEquals(1, Math.sqrt(squares / count - mean * mean), 1e-5);
    }

    @Test
    void everyFrameHasZeroSpatialMean() {
        for (int t = 0; t < FRAMES; t++) {
            double sum = 0;
            for (int i = t * N * N; i < (t + 1) * N * N; i++) {
                sum += field.values()[i];
            }
            assertEquals(0, sum / (N * N), 1e-4, "frame " + t);
        }
    }

    /** A frame's radially averaged power falls as 1/k^β, whatever β, at the default 128 samples. */
    @ParameterizedTest
    @ValueSource(doubles = {1.2, 2, 3})
    void aFramesSpectrumFollowsBeta(double beta) {
        int n = 128;
        CloudField f = CloudField.generate(n, 16, beta, 11);
        double slopes = 0;
        int[] frames = {0, 5, 11};
        for (int t : frames) {
            float[] slice = Arrays.copyOfRange(f.values(), t * n * n, (t + 1) * n * n);
            PowerSpectrum spectrum = PowerSpectrum.of(new HeightMap(n, 1, slice, true));
            // rings 2 .. n/4: away from the few coefficients of ring 1 and the square grid's corners
            slopes += spectrum.fit(1.5 / n, (n / 4 + 0.5) / n).slope() / frames.length;
        }
        assertEquals(-beta, slopes, 0.3, "fitted slope of log power against log frequency");
    }

    @ParameterizedTest
    @ValueSource(doubles = {0, 0.1, 0.45, 0.9, 1})
    void theThresholdLeavesTheCoverAbove(double cover) {
        float threshold = CloudField.coverageThreshold(field, cover);
        long above = 0;
        for (float v : field.values()) {
            if (v > threshold) {
                above++;
            }
        }
        assertEquals(cover, above / (double) field.values().length, 1e-5);
    }

    @Test
    void coverZeroAndOneLieOutsideTheFieldByAMargin() {
        float[] sorted = field.values().clone();
        Arrays.sort(sorted);
        assertTrue(CloudField.coverageThreshold(field, 0) >= sorted[sorted.length - 1] + 0.99f);
        assertTrue(CloudField.coverageThreshold(field, 1) <= sorted[0] - 0.99f);
        assertThrows(IllegalArgumentException.class, () -> CloudField.coverageThreshold(field, 1.1));
    }

    @Test
    void aSeedGivesTheSameFieldBitForBitAndAnotherSeedAnother() {
        CloudField again = CloudField.generate(N, FRAMES, 2, SEED);
        CloudField other = CloudField.generate(N, FRAMES, 2, SEED + 1);

        assertArrayEquals(field.values(), again.values());
        assertFalse(Arrays.equals(field.values(), other.values()));
        double correlation = 0;
        for (int i = 0; i < field.values().length; i++) {
            correlation += field.values()[i] * (double) other.values()[i] / field.values().length;
        }
        assertEquals(0, correlation, 0.2, "fields of different seeds are unrelated");
    }

    @Test
    void sizesMustBePowersOfTwo() {
        assertThrows(IllegalArgumentException.class, () -> CloudField.generate(48, 16, 2, 1));
        assertThrows(IllegalArgumentException.class, () -> CloudField.generate(64, 12, 2, 1));
        assertThrows(IllegalArgumentException.class, () -> CloudField.generate(64, 16, 0, 1));
    }
}

package org.openworld.engine.elevation;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.SpectralSynthesis;
import org.openworld.engine.terrain.heights.TerrainSettings;

/**
 * The synthesised detail continues the model's spectrum: a known 1/f^β world at 4 m is the truth, every fourth sample
 * of it the coarse "model" at 16 m; the detail's β and standard deviation must match what the coarse samples lost.
 */
class DetailBandsTest {

    private static final int FINE_SIDE = 2048;
    private static final int STEP = 4;
    private static final double FINE = 4;
    private static final double BETA = 2.0;
    /** The window whose spectrum is fitted: the largest power of two inside the 512² model, halved for speed. */
    private static final int WINDOW = 256;

    @Test
    void theDetailReplacesWhatTheCoarseModelLost() {
        TerrainSettings world = ElevationImportTest.settings("terrain.size=" + FINE_SIDE, "terrain.spacing=" + FINE,
                "terrain.relief=800", "terrain.beta=" + BETA, "terrain.min-wavelength=8",
                "terrain.max-wavelength=2048");
        HeightMap truth = SpectralSynthesis.generate(world, 7);
        int side = FINE_SIDE / STEP;
        float[] coarse = new float[side * side];
        for (int z = 0; z < side; z++) {
            for (int x = 0; x < side; x++) {
                coarse[z * side + x] = truth.sample(x * STEP, z * STEP);
            }
        }
        ElevationGrid model = new ElevationGrid(side, side, FINE * STEP, FINE * STEP, coarse, Double.NaN, true);
        HeightMap detailed = TileEmbedding.embed(Path.of("model"), model, ElevationImportTest.settings(
                "terrain.size=" + FINE_SIDE, "terrain.spacing=" + FINE), 1, Long.MAX_VALUE);
        assertEquals(FINE, detailed.spacing(), "16 m made 4 times finer, down to terrain.spacing");

        DetailBands bands = DetailBands.measure(centre(coarse, side, WINDOW), WINDOW, FINE * STEP, FINE, 1);
        assertEquals(2, bands.octaves(), "16 m to 4 m: the octaves 8-16 m and 16-32 m");
        // β from a 256² window's ~60 rings, each the mean of 25 or more exponentially distributed powers
        assertEquals(BETA, bands.beta(), 0.15);
        // σ extrapolated from the fitted line: its intercept carries a few per cent of the rings' scatter
        double truthSigma = highPassSigma(truth, 1 / (2 * FINE * STEP));
        assertEquals(truthSigma, bands.sigma(), 0.1 * truthSigma, "the truth's wavelengths below 32 m");

        // and the tile carries it: the detailed tile less the model's cubic, away from the fade, has that σ too
        // (the bands' own sampling scatter over 1.5 km of 8-32 m waves is far below the 10 %)
        int n = detailed.size();
        double sum = 0;
        int count = 0;
        for (int j = n / 4; j < 3 * n / 4; j++) {
            for (int i = n / 4; i < 3 * n / 4; i++) {
                double u = (i - n / 2) * FINE / model.spacingX() + (side - 1) / 2.0;
                double v = (j - n / 2) * FINE / model.spacingZ() + (side - 1) / 2.0;
                double d = detailed.sample(i, j) - TileEmbedding.cubic(model, u, v);
                sum += d * d;
                count++;
            }
        }
        assertEquals(bands.sigma(), Math.sqrt(sum / count), 0.1 * bands.sigma());
    }

    /** The standard deviation of the truth's frequencies above {@code cut} cycles/m: FFT, zero the rest, inverse. */
    private static double highPassSigma(HeightMap map, double cut) {
        int n = map.size();
        float[] a = new float[2 * n * n];
        System.arraycopy(map.heights(), 0, a, 0, n * n);
        org.jtransforms.fft.FloatFFT_2D fft = new org.jtransforms.fft.FloatFFT_2D(n, n);
        fft.realForwardFull(a);
        double extent = map.extent();
        for (int r = 0; r < n; r++) {
            int kz = r < n / 2 ? r : r - n;
            for (int c = 0; c < n; c++) {
                int kx = c < n / 2 ? c : c - n;
                if (Math.hypot(kx, kz) / extent < cut) {
                    a[r * 2 * n + 2 * c] = 0;
                    a[r * 2 * n + 2 * c + 1] = 0;
                }
            }
        }
        fft.complexInverse(a, true);
        double sum = 0;
        for (int i = 0; i < n * n; i++) {
            sum += (double) a[2 * i] * a[2 * i];
        }
        return Math.sqrt(sum / (n * n));
    }

    private static float[] centre(float[] a, int side, int n) {
        float[] c = new float[n * n];
        int o = (side - n) / 2;
        for (int z = 0; z < n; z++) {
            System.arraycopy(a, (z + o) * side + o, c, z * n, n);
        }
        return c;
    }
}

package org.openworld.engine.sky;

import java.util.Arrays;
import java.util.SplittableRandom;
import org.jtransforms.fft.DoubleFFT_3D;
import org.openworld.engine.core.FftThreads;

/**
 * The clouds' density field (paper 2.1: "the clouds density map with a 3D-DFT (2 spatial, 1 temporal)"): a
 * spectrum with random phases and power falling as a power of the frequency, transformed by one inverse complex 3D
 * FFT ({@link DoubleFFT_3D#complexInverse(double[], boolean)} from JTransforms). The result is periodic along all
 * three axes by construction: it tiles the sky without a seam and its evolution loops in time.
 *
 * <h2>The spectrum</h2>
 * For the integer frequency (kx, ky) of the tile and ft of the loop (cycles per tile, cycles per period), with
 * k = √(kx² + ky²), the coefficient is a random unit phasor times the amplitude √P, where
 * <pre>
 *   P(k, ft) = k^−β · h(c·ft / k) / Σ_ft' h(c·ft' / k),     h(u) = (1 + u²)^(−β/2),     c = {@value #TIME_WEIGHT}
 * </pre>
 * h(c·ft/k)·k^−β is the paper's isotropic spectrum 1/f^β over f = √(kx² + ky² + (c·ft)²): a time frequency ft
 * weighs like c spatial ones, so a feature of k cycles per tile changes at about k/c cycles per period, small puffs
 * faster than large banks. The division by the sum over ft (the discrete time frequencies of the loop) shares each
 * spatial frequency's power k^−β out over time instead of adding to it. Without it a frame, which sums all ft, would
 * have a 2D spectrum flatter than β where the time frequencies pile up; with it every frame is a 2D field with
 * power exactly ∝ 1/k^β, the look the setting promises and the tests measure. The spatial mean (k = 0) is 0 for every
 * ft, so the covered fraction of the sky does not pulse through the loop.
 *
 * <p>The real part of the inverse transform is kept (the imaginary part is an independent second field, dropped);
 * it is normalised to mean 0 and standard deviation 1, so a density threshold is in units of the field's spread.
 *
 * <h2>Cost</h2>
 * The complex transform holds 2 doubles per sample: 4 MiB at the default 128 × 128 × 16. Generation takes 30–40 ms
 * there on a 2-core machine once the JIT has warmed up (about 110 ms the first time), and the coverage threshold's
 * sort another 30 ms.
 *
 * <h2>Determinism</h2>
 * As in {@link org.openworld.engine.terrain.heights.SpectralSynthesis}: phases from one {@link SplittableRandom} in index
 * order, drawn as points of the unit disc by rejection (no sin/cos), amplitudes by {@link StrictMath}, and the
 * transform with JTransforms' thread count pinned by {@link FftThreads} under a lock, so a seed gives the same field
 * bit for bit on any number of cores.
 */
public final class CloudField {

    /**
     * Spatial cycles per tile that weigh as much as one temporal cycle per period (c above). At 16 a feature a
     * sixteenth of the tile across (750 m on the default 12 km tile) changes about once per loop, and the smallest the
     * default 128 samples hold (64 cycles per tile) about 4 times, half the Nyquist rate of 16 frames, so linear
     * blending between frames still reads as motion. Consecutive default frames then correlate by about 0.8
     * (at 8: 0.7 and the fine grain flickers).
     */
    static final double TIME_WEIGHT = 16;

    /** Distinguishes the clouds' random stream from the other users of the world seed. */
    private static final long STREAM = 0xC10D_F1E1_D000_0003L;

    private final int resolution;
    private final int frames;
    private final float[] values;

    private CloudField(int resolution, int frames, float[] values) {
        this.resolution = resolution;
        this.frames = frames;
        this.values = values;
    }

    /**
     * A field of {@code resolution² · frames} samples, mean 0 and standard deviation 1.
     *
     * @param resolution samples per side of the tile, a power of two, at least 4
     * @param frames     samples over the period, a power of two, at least 2
     * @param beta       spectral exponent of the power, P ∝ 1/f^β
     * @param seed       the random phases' seed
     */
    public static CloudField generate(int resolution, int frames, double beta, long seed) {
        if (Integer.bitCount(resolution) != 1 || resolution < 4) {
            throw new IllegalArgumentException("resolution must be a power of two, at least 4, got " + resolution);
        }
        if (Integer.bitCount(frames) != 1 || frames < 2) {
            throw new IllegalArgumentException("frames must be a power of two, at least 2, got " + frames);
        }
        if (!(beta > 0)) {
            throw new IllegalArgumentException("beta must be positive, got " + beta);
        }
        double[] a = new double[2 * resolution * resolution * frames];
        fillSpectrum(a, resolution, frames, beta, seed);
        inverseTransform(a, resolution, frames);
        return new CloudField(resolution, frames, normalisedRealPart(a));
    }

    /**
     * Writes the spectrum in JTransforms' complex 3D layout, slices t, rows y, columns x: the pair at
     * 2·((t·n + y)·n + x) holds (kx, ky, ft) with each index i standing for i or i − size above size/2.
     */
    private static void fillSpectrum(double[] a, int n, int m, double beta, long seed) {
        double[] timeShare = timeShares(n, m, beta);
        double quarterBeta = beta / 4;
        SplittableRandom random = new SplittableRandom(seed ^ STREAM);
        for (int t = 0; t < m; t++) {
            long ft = signed(t, m);
            for (int y = 0; y < n; y++) {
                long ky = signed(y, n);
                for (int x = 0; x < n; x++) {
                    long kx = signed(x, n);
                    long k2 = kx * kx + ky * ky;
                    if (k2 == 0) {
                        continue; // the spatial mean stays 0 in every frame
                    }
                    // √P = k^(−β/2) · √(share of this ft); exp(log) is specified bit for bit like pow
                    double amplitude = StrictMath.exp(-quarterBeta * StrictMath.log(k2))
                            * Math.sqrt(timeShare[(t * n + y) * n + x]);
                    double px;
                    double py;
                    double d2;
                    do { // a uniform direction: a point uniform in the unit disc, by rejection from the square
                        px = 2 * random.nextDouble() - 1;
                        py = 2 * random.nextDouble() - 1;
                        d2 = px * px + py * py;
                    } while (d2 > 1 || d2 == 0);
                    double scale = amplitude / Math.sqrt(d2);
                    int i = 2 * ((t * n + y) * n + x);
                    a[i] = px * scale;
                    a[i + 1] = py * scale;
                }
            }
        }
    }

    /** h(c·ft/k) / Σ_ft' h(c·ft'/k) for every sample of the spectrum (0 where k = 0), same layout as the values. */
    private static double[] timeShares(int n, int m, double beta) {
        double halfBeta = beta / 2;
        double[] share = new double[n * n * m];
        double[] h = new double[m];
        for (int y = 0; y < n; y++) {
            long ky = signed(y, n);
            for (int x = 0; x < n; x++) {
                long kx = signed(x, n);
                long k2 = kx * kx + ky * ky;
                if (k2 == 0) {
                    continue;
                }
                double sum = 0;
                for (int t = 0; t < m; t++) {
                    double u = TIME_WEIGHT * signed(t, m);
                    h[t] = StrictMath.exp(-halfBeta * StrictMath.log1p(u * u / k2));
                    sum += h[t];
                }
                for (int t = 0; t < m; t++) {
                    share[(t * n + y) * n + x] = h[t] / sum;
                }
            }
        }
        return share;
    }

    /** Index i of an axis of the given size as a signed frequency: i below size/2, else i − size. */
    private static long signed(int i, int size) {
        return i < size / 2 ? i : i - size;
    }

    /** The in-place inverse transform with JTransforms' thread count pinned (see the class comment). */
    private static void inverseTransform(double[] a, int n, int m) {
        // No 1/N scaling: the normalisation rescales anyway.
        FftThreads.pinned(() -> new DoubleFFT_3D(m, n, n).complexInverse(a, false));
    }

    /** The real parts, shifted and scaled to mean 0 and standard deviation 1. */
    private static float[] normalisedRealPart(double[] a) {
        int count = a.length / 2;
        double sum = 0;
        for (int i = 0; i < count; i++) {
            sum += a[2 * i];
        }
        double mean = sum / count;
        double squares = 0;
        for (int i = 0; i < count; i++) {
            double d = a[2 * i] - mean;
            squares += d * d;
        }
        double std = Math.sqrt(squares / count);
        if (!(std > 0)) {
            throw new IllegalStateException("the cloud field came out flat");
        }
        float[] values = new float[count];
        for (int i = 0; i < count; i++) {
            values[i] = (float) ((a[2 * i] - mean) / std);
        }
        return values;
    }

    /**
     * The density below which a fraction {@code 1 − cover} of the field's samples lie, so that {@code cover} of them
     * are above it: the threshold the shader turns into opacity. Cover 0 gives a value above the maximum, cover 1
     * one below the minimum (both one standard deviation out), so no sample, or every one, counts as cloud.
     */
    public static float coverageThreshold(CloudField field, double cover) {
        if (!(cover >= 0 && cover <= 1)) {
            throw new IllegalArgumentException("cover must lie in [0, 1], got " + cover);
        }
        float[] sorted = field.values.clone();
        Arrays.sort(sorted);
        int count = sorted.length;
        int above = (int) Math.round(cover * count);
        if (above == 0) {
            return sorted[count - 1] + 1;
        }
        if (above == count) {
            return sorted[0] - 1;
        }
        // halfway between the highest sample left out and the lowest one counted
        return (sorted[count - above - 1] + sorted[count - above]) / 2;
    }

    public int resolution() {
        return resolution;
    }

    public int frames() {
        return frames;
    }

    /** The density at sample (x, y) of frame t; every index wraps, as the field is periodic. */
    public float density(int x, int y, int t) {
        int n = resolution;
        return values[(Math.floorMod(t, frames) * n + Math.floorMod(y, n)) * n + Math.floorMod(x, n)];
    }

    /**
     * The samples, x fastest, then y, then t: the layout of a 3D texture's upload (width = height = resolution,
     * depth = frames). The array is the field's own; do not change it.
     */
    public float[] values() {
        return values;
    }
}

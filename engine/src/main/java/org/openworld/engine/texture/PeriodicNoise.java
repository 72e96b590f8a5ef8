package org.openworld.engine.texture;

import java.util.SplittableRandom;
import org.jtransforms.fft.DoubleFFT_2D;
import org.openworld.engine.core.FftThreads;

/**
 * Periodic Gaussian noise on a square tile, shaped in the frequency domain: the raw material of every
 * recipe (the terrain's {@code MaterialRecipes}, the plants' {@code BarkTextures}). The same idea as the terrain's
 * height map ({@link org.openworld.engine.terrain.heights.SpectralSynthesis}), at texture
 * scale.
 *
 * <p><b>Method.</b> For every integer frequency (fx, fy), cycles per tile with fx, fy in (−n/2, n/2], draw a complex
 * coefficient whose two parts are independent Gaussians times the amplitude {@code A(fx² + fy²)} of a radial
 * {@link Spectrum}; the mean (0, 0) stays 0. One unscaled inverse FFT
 * ({@link DoubleFFT_2D#complexInverse(double[], boolean)}) brings them back to texels. Because the coefficients are
 * not conjugate-symmetric, the result is complex: its real and imaginary parts are two <em>independent</em> real
 * fields of the same spectrum, so one transform gives a pair ({@link #pair}). Each field is then standardised to
 * mean 0 and variance 1, so a recipe's constants say "so many standard deviations".
 *
 * <p><b>Tileable by construction.</b> Only whole cycles per tile exist, so the field is periodic: the texel right of
 * the last column is the first column, as smooth a neighbour as any interior pair.
 *
 * <p><b>The band.</b> {@link #band} is 1/f^β in power (amplitude f^(−β/2)) between soft edges at {@code low} and
 * {@code high} cycles per tile: {@code A(f²) = exp(−(low²/f²)² − (f²/high²)²) · f^(−β/2)}. β = 0 is white noise in the
 * band, 2 the rough relief of rock, 3 the smooth swell of snow drifts. Coefficients whose exponent passes 20
 * ({@code exp(−20)} = 2·10⁻⁹ of the peak, nothing visible at 8 bits) are zero and draw no random numbers.
 *
 * <p><b>Cost.</b> n² coefficients and one complex n² inverse FFT, O(n² log n): about 16 ms for a pair at 512² on
 * the 2-core reference machine, JIT warm. The transform runs through {@link FftThreads#pinned}, so JTransforms'
 * thread count is the same on every machine and a seed gives the same texels bit for bit; concurrent callers'
 * transforms take turns behind its lock (each using the pinned threads meanwhile).
 *
 * <p><b>Limits.</b> Gaussian: no ridges, no sharp edges; the recipes add those by thresholds, cells and stamping.
 * Isotropic: the spectrum is radial, every direction alike.
 */
public final class PeriodicNoise {

    /**
     * A radial amplitude spectrum over integer frequencies (cycles per tile), given the squared frequency
     * fx² + fy²; zero outside the band it was made for, so those coefficients cost no random numbers.
     */
    @FunctionalInterface
    public interface Spectrum {
        double amplitude(double f2);
    }

    private final int n;

    /** Noise on tiles of {@code n}² texels, {@code n} a power of two. */
    public PeriodicNoise(int n) {
        this.n = n;
    }

    /**
     * Two independent periodic Gaussian fields with the given amplitude spectrum, each of zero mean and unit
     * variance, texel (x, y) at {@code y n + x}. The coefficients are drawn from {@code rng} rows then columns.
     */
    public double[][] pair(SplittableRandom rng, Spectrum spectrum) {
        double[] a = new double[2 * n * n];
        for (int ky = 0; ky < n; ky++) {
            int fy = ky <= n / 2 ? ky : ky - n;
            for (int kx = 0; kx < n; kx++) {
                int fx = kx <= n / 2 ? kx : kx - n;
                double amplitude = fx == 0 && fy == 0 ? 0 : spectrum.amplitude(fx * fx + fy * fy);
                if (amplitude > 1e-9) {
                    int i = 2 * (ky * n + kx);
                    a[i] = amplitude * rng.nextGaussian();
                    a[i + 1] = amplitude * rng.nextGaussian();
                }
            }
        }
        FftThreads.pinned(() -> new DoubleFFT_2D(n, n).complexInverse(a, false));
        double[] re = new double[n * n];
        double[] im = new double[n * n];
        for (int i = 0; i < n * n; i++) {
            re[i] = a[2 * i];
            im[i] = a[2 * i + 1];
        }
        return new double[][] {standardise(re), standardise(im)};
    }

    /**
     * 1/f^β power (amplitude f^(−β/2)) between soft edges at {@code low} and {@code high} cycles per tile (see the
     * class comment).
     */
    public static Spectrum band(double low, double high, double beta) {
        double low2 = low * low;
        double high2 = high * high;
        return f2 -> {
            double below = low2 / f2;
            double above = f2 / high2;
            double exponent = below * below + above * above;
            // beyond exp(−20) = 2e−9 of the peak: nothing visible at 8 bits
            return exponent > 20 ? 0 : Math.exp(-exponent - beta / 4 * Math.log(f2));
        };
    }

    /** Shifts and scales {@code v} in place to mean 0 and variance 1; returns it. */
    private static double[] standardise(double[] v) {
        double[] moments = meanAndDeviation(v);
        double scale = 1 / moments[1];
        for (int i = 0; i < v.length; i++) {
            v[i] = (v[i] - moments[0]) * scale;
        }
        return v;
    }

    /** {mean, standard deviation} of {@code v}, in two passes (the second around the mean, so no cancellation). */
    static double[] meanAndDeviation(double[] v) {
        double mean = 0;
        for (double x : v) {
            mean += x;
        }
        mean /= v.length;
        double var = 0;
        for (double x : v) {
            var += (x - mean) * (x - mean);
        }
        return new double[] {mean, Math.sqrt(var / v.length)};
    }
}

package org.openworld.engine.terrain.heights;

import java.util.SplittableRandom;
import java.util.stream.IntStream;
import org.jtransforms.fft.FloatFFT_2D;
import org.openworld.engine.core.FftThreads;

/**
 * Height maps by spectral synthesis (paper 2.1): a spectrum with random phases and amplitude 1/ω^β, transformed to
 * heights by one inverse real 2D FFT ({@link FloatFFT_2D#realInverse(float[], boolean)} from JTransforms).
 *
 * <h2>The spectrum</h2>
 * For the integer frequency (kx, kz) of the tile (kx, kz cycles across it, ω = √(kx² + kz²) / extent) the
 * coefficient is {@code ω^−β · (cos φ, sin φ)} with φ uniform in [0, 2π). Frequencies whose wavelength 1/ω lies
 * outside ({@code minWavelength}, {@code maxWavelength}] get 0, and the mean (ω = 0) is 0 too. The short end is open
 * so that octave bands ({@link BandedHeights}) cut at the same wavelength share no frequency. The Nyquist row and
 * column (kx or kz = size/2) stay 0 as well: on the grid a wave at the Nyquist frequency can only be a cosine, so its
 * phase cannot be random. The inverse DFT of such a spectrum is periodic, so copies of the tile join without a seam.
 *
 * <h2>Choosing β</h2>
 * β decides how rough the ground is at the scale of the samples. Each octave of frequencies adds slope variance
 * ∝ ω^(4−2β): for β ≤ 2 the octaves down to the 2 m samples add as much steepness as the big ones, and hillshades of
 * the default 4 km, 800 m tile look like crumpled paper (mean slope 54° at β = 1.8, 41° at β = 2). At β = 2.2, the
 * default, the large ranges dominate: separate massifs and valleys with finer texture on them, mean slope 34° and a
 * fifth of the ground steeper than 45°, like alpine terrain. β = 1, the paper's literal 1/ω, is spiky noise.
 *
 * <p>Amplitudes are deterministic and only phases random, so the radially averaged power spectrum of the result
 * has slope −2β on a log-log plot (see {@link PowerSpectrum}): what the tests check.
 *
 * <h2>Memory</h2>
 * The spectrum is written straight into JTransforms' packed layout for real 2D data (one {@code float} per sample;
 * Hermitian symmetry makes the other half redundant) and transformed in place, so the height array is the only
 * large allocation: {@code 4 · size²} bytes, 64 MiB at 4096², 256 MiB at 8192².
 *
 * <h2>Determinism</h2>
 * One seed and one set of settings give the same heights bit for bit, whatever the number of cores:
 * <ul>
 *   <li>each spectrum row draws from its own {@link SplittableRandom} (a specified algorithm), seeded in row order
 *       from the world seed, so rows can be filled in parallel in any order; phases are uniform points on the unit
 *       circle drawn by rejection from the square (needs {@link Math#sqrt}, exact in IEEE arithmetic, not sin/cos)
 *       and amplitudes use {@link StrictMath#exp} and {@link StrictMath#log}, specified bit for bit;</li>
 *   <li>JTransforms picks different code paths by its thread count, so the transform runs with that count
 *       <em>pinned</em> by {@link FftThreads} and restored afterwards (under a lock, as the count is global).</li>
 * </ul>
 * One caveat: JTransforms computes its twiddle factors with {@link Math#sin}/{@link Math#cos}, which Java lets
 * differ by an ulp between JVM platforms; on one platform (all x86-64 HotSpot JVMs, say) results are identical.
 */
public final class SpectralSynthesis {

    /**
    /** Distinguishes the synthesis' random stream from the other users of the world seed (the snow map). */
    private static final long STREAM = 0x5EED_7E44_A1B5_0001L;

    /** Below this many samples per side a row loop is cheaper than forking it out to other threads. */
    private static final int PARALLEL_MIN_SIZE = 512;

    private SpectralSynthesis() {
    }

    /**
     * A periodic height map of {@code s.size()²} samples {@code s.spacing()} apart, normalised so that its heights
     * span {@code s.relief()} metres with {@code s.seaFraction()} of them below 0.
     */
    public static HeightMap generate(TerrainSettings s, int seed) {
        int n = s.size();
        float[] a = new float[n * n];
        fillSpectrum(a, n, s.extent(), s.beta(), s.minWavelength(), s.maxWavelength(), seed ^ STREAM);
        inverseTransform(a, n);
        normalise(a, n, s.relief(), s.seaFraction());
        return new HeightMap(n, s.spacing(), a, true);
    }

    /**
     * Writes the random spectrum into {@code a} in the packed layout of {@link FloatFFT_2D#realForward(float[])}:
     * row r holds kz = r (r &lt; n/2) or r − n (r &gt; n/2); within a row, slots 2kx and 2kx + 1 hold the real and
     * imaginary part of (kx, kz) for 0 &lt; kx &lt; n/2. Slot pair 0, 1 holds (kx = 0, kz = r) in rows
     * 0 &lt; r &lt; n/2 (the conjugates at −kz follow from symmetry), and Nyquist or mean terms everywhere else:
     * those stay 0. The coefficients are {@code k^−β} for k cycles per tile (multiply by {@code extent^β} for
     * ω^−β in cycles per metre); {@code stream} seeds the random phases.
     */
    static void fillSpectrum(float[] a, int n, double extent, double beta, double minWavelength,
                             double maxWavelength, long stream) {
        // cut-offs as squared integer frequencies: k cycles per tile has wavelength extent / k
        double kLow = extent / maxWavelength;
        double kHigh = extent / minWavelength;
        double k2Low = kLow * kLow;
        double k2High = kHigh * kHigh;
        double halfBeta = beta / 2;

        SplittableRandom root = new SplittableRandom(stream);
        long[] rowSeeds = new long[n];
        for (int r = 0; r < n; r++) {
            rowSeeds[r] = root.nextLong();
        }
        rows(n).forEach(r -> {
            if (r == n / 2) {
                return; // the Nyquist row kz = n/2
            }
            SplittableRandom random = new SplittableRandom(rowSeeds[r]);
            long kz = r < n / 2 ? r : r - n;
            int firstKx = r > 0 && r < n / 2 ? 0 : 1; // slot 0 of the other rows holds Nyquist or mean terms
            for (int kx = firstKx; kx < n / 2; kx++) {
                long k2 = kx * (long) kx + kz * kz;
                if (k2 < k2Low || k2 >= k2High) {
                    continue;
                }
                // (√k2)^−β; exp(log) is specified bit for bit like pow, and five times faster
                double amplitude = StrictMath.exp(-halfBeta * StrictMath.log(k2));
                double x;
                double y;
                double d2;
                do { // a uniform direction: a point uniform in the unit disc, by rejection from the square
                    x = 2 * random.nextDouble() - 1;
                    y = 2 * random.nextDouble() - 1;
                    d2 = x * x + y * y;
                } while (d2 > 1 || d2 == 0);
                double scale = amplitude / Math.sqrt(d2);
                a[r * n + 2 * kx] = (float) (x * scale);
                a[r * n + 2 * kx + 1] = (float) (y * scale);
            }
        });
    }

    /** The in-place inverse transform with JTransforms' thread count pinned (see the class comment). */
    static void inverseTransform(float[] a, int n) {
        // No 1/n² scaling: the normalisation rescales anyway.
        FftThreads.pinned(() -> new FloatFFT_2D(n, n).realInverse(a, false));
    }

    /** h = relief · (f' − seaFraction), where f' is f scaled to [0, 1] by the field's own minimum and maximum. */
    public static void normalise(float[] a, int n, double relief, double seaFraction) {
        float[] rowMin = new float[n];
        float[] rowMax = new float[n];
        rows(n).forEach(r -> {
            float lo = Float.POSITIVE_INFINITY;
            float hi = Float.NEGATIVE_INFINITY;
            for (int i = r * n; i < (r + 1) * n; i++) {
                lo = Math.min(lo, a[i]);
                hi = Math.max(hi, a[i]);
            }
            rowMin[r] = lo;
            rowMax[r] = hi;
        });
        float lo = Float.POSITIVE_INFINITY;
        float hi = Float.NEGATIVE_INFINITY;
        for (int r = 0; r < n; r++) {
            lo = Math.min(lo, rowMin[r]);
            hi = Math.max(hi, rowMax[r]);
        }
        double min = lo;
        double range = hi - min;
        if (!(range > 0)) {
            throw new IllegalArgumentException("the height field is flat: no frequency lies between the cut-offs");
        }
        rows(n).forEach(r -> {
            for (int i = r * n; i < (r + 1) * n; i++) {
                a[i] = (float) (relief * ((a[i] - min) / range - seaFraction));
            }
        });
    }

    /** Row indices 0 .. n−1, in parallel for large maps; each row's work must not depend on the others. */
    static IntStream rows(int n) {
        IntStream rows = IntStream.range(0, n);
        return n >= PARALLEL_MIN_SIZE ? rows.parallel() : rows;
    }
}

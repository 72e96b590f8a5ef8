package org.openworld.engine.water;

import java.util.Random;

/**
 * The ripples' waves in the frequency domain: Phillips' wind-sea spectrum on the tile's lattice of wave vectors, and
 * their motion by the deep-water dispersion relation quantised so that the field loops. {@link RippleField} turns
 * them into frames. The derivation is in {@code docs/water.md}, section "The ripples, derived"; in short:
 * <pre>
 *   k = 2π (m, n) / tile,   m, n in (−size/2, size/2)               (m along x, n along z, rad/m)
 *   P(k) = exp(−1 / (k L)²) / k⁴ · |k̂·ŵ|² · exp(−k² ℓ²),   L = V² / g,   ℓ = L / 1000
 *   h0(k) = (ξr + i ξi) / √2 · √P(k)                           ({@link Random#nextGaussian()})
 *   ω(k) = floor(√(g k) / ω0) · ω0,   ω0 = 2π / period          (so the field repeats after one period)
 *   h(k, t) = h0(k) e^{−iωt} + conj(h0(−k)) e^{+iωt}           (h(−k, t) = conj(h(k, t)): a real height)
 * </pre>
 * Waves running against the wind (k̂·ŵ &lt; 0) keep {@link #AGAINST_WIND_POWER} of Phillips' power. k = 0 and the
 * Nyquist row and column carry nothing. Phillips' constant A is left out: {@link RippleField} rescales to a slope.
 *
 * <p><b>Determinism.</b> The amplitudes come from one {@link Random} seeded with the world seed mixed with this
 * class's own stream constant ({@code STREAM}), two Gaussian numbers per lattice index, rows then columns: the same
 * seed and arguments give the same waves on every machine, another seed other waves.
 *
 * <p><b>Cost.</b> size² exponentials at construction; {@link #at} takes size² sines and cosines.
 *
 * <p><b>Limits.</b> Phillips' spreading makes the slope variance along the wind 3× that across it (Cox and Munk
 * measured about 1.4× at 10 m/s); deep water only, no capillary term; quantising ω slows every wave by less than ω0
 * and stops those with √(g k) &lt; ω0.
 */
final class RippleSpectrum {

    /** Acceleration of gravity, m/s². */
    static final double GRAVITY = 9.81;

    /**
     * Factor on the power of waves running against the wind (k̂·ŵ &lt; 0), about 0.26 on their amplitude: a wind sea
     * carries little energy upwind, but not none (measured directional spreading, Longuet-Higgins' cos^{2s}(θ/2)
     * for one, leaves some beyond 90° from the wind), and a little counter-running sea keeps the pattern from
     * sliding along as one piece. The value of NVIDIA's CUDA "oceanFFT" sample.
     */
    static final double AGAINST_WIND_POWER = 0.07;

    /** ℓ / L: waves shorter than this fraction of the largest wind wave L are suppressed (Tessendorf's choice). */
    static final double SMALL_WAVE_FRACTION = 1e-3;

    /**
     * XOR-ed into the world seed to give the ripples' stream its own seed (a {@link Random}, no other user of the
     * world seed draws from one). 2016, so that the default world seed 1 draws {@code new Random(2017)}, the waves
     * the water had before it followed the world seed: every picture in {@code docs/} stays what its command makes.
     */
    private static final long STREAM = 2016;

    private final int size;
    private final double tileMetres;
    /** h0(k), real and imaginary parts interleaved at 2i, i = row · size + column. */
    private final double[] h0;
    /** ω(k) / ω0 per lattice index i: the whole number of cycles each wave completes per period. */
    private final double[] cyclesPerPeriod;

    private RippleSpectrum(int size, double tileMetres, double[] h0, double[] cyclesPerPeriod) {
        this.size = size;
        this.tileMetres = tileMetres;
        this.h0 = h0;
        this.cyclesPerPeriod = cyclesPerPeriod;
    }

    /**
     * The waves of a wind over a tile, their largest amplitude brought to 1 (only the shape matters: the field
     * rescales it, and a faint spectrum, a weak wind on a fine tile, must not underflow in the Parseval sum).
     * Arguments as {@link RippleField#synthesize}, already checked.
     *
     * @throws IllegalArgumentException naming windSpeed when the wind raises no wave the tile resolves
     */
    static RippleSpectrum of(int size, double tileMetres, double periodSeconds, double windSpeed,
            double windDirectionDegrees, long seed) {
        double[] h0 = phillipsAmplitudes(size, tileMetres, windSpeed, windDirectionDegrees, seed);
        double largest = 0;
        for (double a : h0) {
            largest = Math.max(largest, Math.abs(a));
        }
        if (!(largest > 0)) {
            throw new IllegalArgumentException("windSpeed " + windSpeed + " m/s raises no wave the tile resolves: "
                    + "its largest waves, V²/g = " + windSpeed * windSpeed / GRAVITY + " m, are far shorter than "
                    + "the " + tileMetres / size + " m texels; use a stronger wind or a finer tile");
        }
        for (int i = 0; i < h0.length; i++) {
            h0[i] /= largest;
        }
        double dk = 2 * Math.PI / tileMetres;
        double[] cycles = new double[size * size];
        for (int r = 0; r < size; r++) {
            for (int c = 0; c < size; c++) {
                cycles[r * size + c] = cyclesPerPeriod(dk * Math.hypot(frequency(c, size), frequency(r, size)),
                        periodSeconds);
            }
        }
        return new RippleSpectrum(size, tileMetres, h0, cycles);
    }

    /**
     * h0(k) for every lattice index, real and imaginary parts interleaved; 0 at k = 0 and on the Nyquist row and
     * column. Two Gaussian numbers are drawn per remaining index, rows n then columns m in index order.
     */
    private static double[] phillipsAmplitudes(int size, double tileMetres, double windSpeed,
            double windDirectionDegrees, long seed) {
        double yaw = Math.toRadians(windDirectionDegrees);
        double windX = Math.sin(yaw); // yaw 90°: towards +X (east)
        double windZ = -Math.cos(yaw); // yaw 0°: towards −Z (north)
        double largestWave = windSpeed * windSpeed / GRAVITY; // L, metres
        double smallestWave = SMALL_WAVE_FRACTION * largestWave; // ℓ, metres
        double dk = 2 * Math.PI / tileMetres;
        Random random = new Random(seed ^ STREAM);
        double[] h0 = new double[2 * size * size];
        for (int r = 0; r < size; r++) {
            int n = frequency(r, size);
            for (int c = 0; c < size; c++) {
                int m = frequency(c, size);
                if (m == 0 && n == 0 || m == -size / 2 || n == -size / 2) {
                    continue; // the mean level and the Nyquist row and column carry nothing
                }
                double kx = dk * m;
                double kz = dk * n;
                double k2 = kx * kx + kz * kz;
                double cosine = (kx * windX + kz * windZ) / Math.sqrt(k2); // k̂·ŵ
                double power = StrictMath.exp(-1 / (k2 * largestWave * largestWave) - k2 * smallestWave * smallestWave)
                        / (k2 * k2) * cosine * cosine;
                if (cosine < 0) {
                    power *= AGAINST_WIND_POWER;
                }
                double amplitude = Math.sqrt(power / 2); // (ξr + i ξi) / √2 · √P
                int i = r * size + c;
                h0[2 * i] = random.nextGaussian() * amplitude;
                h0[2 * i + 1] = random.nextGaussian() * amplitude;
            }
        }
        return h0;
    }

    /**
     * The quantised dispersion relation: the whole number of cycles per period, floor(√(g k) / ω0) with
     * ω0 = 2π / periodSeconds, of a deep-water wave of wavenumber k rad/m. Its angular frequency is that number
     * times ω0, within ω0 below √(g k).
     */
    static double cyclesPerPeriod(double k, double periodSeconds) {
        return Math.floor(Math.sqrt(GRAVITY * k) * periodSeconds / (2 * Math.PI));
    }

    /** The frequency (cycles per tile) held at index j of a row or column of a size-point transform. */
    static int frequency(int j, int size) {
        return j < size / 2 ? j : j - size;
    }

    /** Lattice points per side. */
    int size() {
        return size;
    }

    /** The lattice spacing Δk = 2π / tile, rad/m. */
    double dk() {
        return 2 * Math.PI / tileMetres;
    }

    /**
     * Writes h(k, t) = h0(k) e^{−iωt} + conj(h0(−k)) e^{+iωt} for every lattice index into {@code out} (real and
     * imaginary interleaved), at {@code periods} = t / period. The phase ω t = 2π · cycles · t / period is reduced
     * to its fraction of a turn first, so whole periods give exactly the same phases.
     */
    void at(double periods, double[] out) {
        for (int r = 0; r < size; r++) {
            int mirrorRow = (size - r) & (size - 1); // −n
            for (int c = 0; c < size; c++) {
                int i = r * size + c;
                int j = mirrorRow * size + ((size - c) & (size - 1)); // the index of −k
                double ar = h0[2 * i];
                double ai = h0[2 * i + 1];
                double br = h0[2 * j];
                double bi = h0[2 * j + 1];
                double turns = cyclesPerPeriod[i] * periods;
                double phase = 2 * Math.PI * (turns - Math.floor(turns));
                double cos = Math.cos(phase);
                double sin = Math.sin(phase);
                // (ar + i ai)(cos − i sin) + (br − i bi)(cos + i sin)
                out[2 * i] = (ar + br) * cos + (ai + bi) * sin;
                out[2 * i + 1] = (ai - bi) * cos + (br - ar) * sin;
            }
        }
    }

    /**
     * The mean square slope over {@code frames} evenly spaced moments of one period, by Parseval's theorem without
     * any transform: the mean of |f|² over the texels of an unscaled inverse transform is Σ_k |F(k)|², so a frame's
     * mean of sx² + sz² is Σ_k |k|² |h(k, t)|².
     */
    double meanSquareSlope(int frames) {
        double dk = dk();
        double[] h = new double[2 * size * size];
        double sum = 0;
        for (int f = 0; f < frames; f++) {
            at(f / (double) frames, h);
            for (int r = 0; r < size; r++) {
                int n = frequency(r, size);
                for (int c = 0; c < size; c++) {
                    int m = frequency(c, size);
                    int i = r * size + c;
                    sum += dk * dk * (m * m + n * n) * (h[2 * i] * h[2 * i] + h[2 * i + 1] * h[2 * i + 1]);
                }
            }
        }
        return sum / frames;
    }

    /** Multiplies every amplitude by {@code factor}, in place: the slopes and heights scale with it. */
    void scale(double factor) {
        for (int i = 0; i < h0.length; i++) {
            h0[i] *= factor;
        }
    }
}

package org.openworld.engine.water;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Random;
import org.jtransforms.fft.FloatFFT_2D;
import org.openworld.engine.core.FftThreads;

/**
 * The water's ripples: a periodic tile of wind-driven waves that loops in time, synthesised once on the CPU as
 * Tessendorf's FFT ocean (J. Tessendorf, "Simulating Ocean Water", SIGGRAPH course notes 2001) and handed to the
 * shader as {@link #frames()} layers of surface slopes.
 *
 * <h2>The spectrum</h2>
 * The tile is {@link #tileMetres()} wide and sampled by {@link #size()}² texels Δ = tile / size apart. Periodic
 * waves on it have the lattice wave vectors k = 2π (m, n) / tile (m along x, n along z, rad/m) with m, n in
 * (−size/2, size/2). Each gets a random complex amplitude from the Phillips spectrum
 * <pre>
 *   P(k) = exp(−1 / (k L)²) / k⁴ · |k̂·ŵ|² · exp(−k² ℓ²),   L = V² / g,   ℓ = L / 1000
 *   h0(k) = (ξr + i ξi) / √2 · √P(k),                     ξr, ξi standard Gaussian ({@link Random#nextGaussian()})
 * </pre>
 * L is the length of the largest waves a steady wind of V m/s raises (the 1/(kL)² factor cuts off longer ones),
 * k⁻⁴ is Phillips' saturation range of a wind sea, |k̂·ŵ|² favours waves running along the wind direction ŵ, and
 * exp(−k² ℓ²) fades waves shorter than a thousandth of L. Waves whose k̂·ŵ &lt; 0 run <em>against</em> the wind:
 * Phillips' |k̂·ŵ|² is even in k̂ and would give them as much energy as those running with it, but wind only feeds
 * waves that move with it and waves opposing it lose energy to the air, so their power is multiplied by
 * {@link #AGAINST_WIND_POWER}. The constant amplitude factor of the usual statement (Phillips' A) is left out: the
 * field is rescaled to a chosen slope anyway. k = 0 (the mean level) and the Nyquist row and column (m or n =
 * −size/2) carry nothing: on the grid a Nyquist wave can only be a cosine, whose spectral derivative i·k·h would
 * sample to zero at every texel (sin of a multiple of π), so it has no slope to show and would break the
 * conjugate symmetry that makes the slopes real.
 *
 * <h2>Motion and the looping trick</h2>
 * Deep-water waves obey the dispersion relation ω(k) = √(g k). Tessendorf's trick for a loop of period T:
 * quantise every ω to a whole multiple of ω0 = 2π / T, ω = floor(√(g k) / ω0) · ω0 ({@link #cyclesPerPeriod}),
 * so every wave, and so the whole field, repeats after exactly T seconds. The field at time t is
 * <pre>
 *   h(k, t) = h0(k) e^{−iωt} + conj(h0(−k)) e^{+iωt},     h(x, t) = Σ_k h(k, t) e^{i k·x}
 * </pre>
 * The first term is the wave h0(k) e^{i(k·x − ωt)}, travelling along +k, and the second its mirror image, which
 * makes h(−k, t) = conj(h(k, t)) and the height real. (Tessendorf's notes write e^{+iωt} on h0(k): with the same
 * e^{+ik·x} that wave travels along −k, harmless for his symmetric spectrum but here it would send the damped,
 * upwind waves downwind and the strong ones upwind.) Frame f is the field at t = f · T / frames.
 *
 * <h2>Slopes by spectral derivative</h2>
 * ∂/∂x of e^{ik·x} is i kx e^{ik·x}, so the slopes are the transforms of i kx h(k, t) and i kz h(k, t): exact
 * derivatives of the waves, with none of the blur of a finite difference. Both slopes are real fields, so one
 * complex transform carries the pair: the inverse transform of i kx h + i (i kz h) = h (i kx − kz) is sx + i sz.
 * The height h(x, t) takes a second transform. Both are {@link FloatFFT_2D#complexInverse(float[], boolean)} of
 * JTransforms, unscaled, whose sign convention a[x] = Σ A[k] e^{+2πi k x / N} is the synthesis sum above; index
 * j of a row or column holds frequency j for j &lt; size/2 and j − size above ({@link #frequency}).
 *
 * <h2>Amplitude</h2>
 * The slopes are scaled so that their total RMS, √(mean of sx² + sz² over all texels and frames), is the caller's
 * {@code rmsSlope}. The scale is found before any transform, by Parseval's theorem: the mean of |f|² over the
 * texels of an unscaled inverse transform is Σ_k |F(k)|², so the mean square slope of a frame is
 * Σ_k |k|² |h(k, t)|². The intended target is Cox and Munk's clean-surface mean square slope, measured from sun
 * glitter photographs (C. Cox, W. Munk, "Measurement of the roughness of the sea surface from photographs of the
 * sun's glitter", JOSA 44, 1954): σ² = 0.003 + 0.00512 V for wind V m/s at 12.5 m, so the water system passes
 * √(0.003 + 0.00512 V), possibly scaled. This class honours whatever it is given.
 *
 * <h2>Cost</h2>
 * At start-up, O(F · N² log N) for F frames of N² texels: per frame, N² sines and cosines for the wave phases
 * (twice: once for the amplitude, once for the frame) and two complex N² transforms. Nothing per rendered frame:
 * the shader only looks the slopes up. 128² texels × 32 frames take 0.10 to 0.15 s (0.26 s on a cold JVM) on a
 * 2-core machine, plus 11 ms for {@link #texels}, and hold 6 MiB of floats. JTransforms' thread count is pinned
 * by {@link FftThreads} during the transforms, as for the terrain and the clouds, so the result cannot depend
 * on the machine; below 256² texels (its threshold for 2D transforms) JTransforms runs on the calling thread
 * anyway.
 *
 * <h2>Limits</h2>
 * <ul>
 *   <li>The tile repeats: no wave is longer than the tile or shorter than two texels. The shader hides the
 *       repetition by sampling the tile at two scales.</li>
 *   <li>Linear waves: heights add, crests are as round as troughs, nothing steepens, breaks or foams (Tessendorf's
 *       horizontal "choppy" displacement is not included).</li>
 *   <li>Phillips' |k̂·ŵ|² spreading makes the slope variance along the wind 3× that across it (∫cos⁴ / ∫cos²sin²);
 *       Cox and Munk measured about 1.4× at 10 m/s (0.00316 V upwind, 0.003 + 0.00192 V crosswind).</li>
 *   <li>Deep water only, and no capillary term: surface tension speeds up waves of a few centimetres and
 *       shorter.</li>
 *   <li>Quantising ω slows every wave slightly (by less than ω0), and waves with √(g k) &lt; ω0 stand still: a
 *       period of a few tens of seconds keeps both unnoticeable.</li>
 * </ul>
 */
final class RippleField {

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


    /** Smallest tile side, texels: fewer leaves hardly any waves between the mean and the Nyquist frequency. */
    static final int MIN_SIZE = 8;

    /** Largest tile side, texels: 4096² floats are 64 MiB per layer, already far beyond a ripple texture. */
    static final int MAX_SIZE = 4096;

    /** The height channel of {@link #texels} spans ± this many RMS heights (beyond 3σ is rare: 0.3 % of texels). */
    static final double HEIGHT_RANGE_IN_RMS = 3;


    private final int size;
    private final int frames;
    private final double tileMetres;
    private final double periodSeconds;
    /** h0(k) scaled to the target slope, real and imaginary parts interleaved at 2i, i = row · size + column. */
    private final double[] h0;
    /** ω(k) / ω0 per lattice index i: the whole number of cycles each wave completes per period. */
    private final double[] cyclesPerPeriod;
    private final List<Frame> layers;
    private final double rmsSlope;
    private final double rmsHeight;

    /**
     * One moment of the field, texels in rows z = 0.., x fastest.
     *
     * @param size    texels per side
     * @param slopes  2 · size² floats: ∂h/∂x and ∂h/∂z of each texel, interleaved; shared, not copied
     * @param heights size² floats: h of each texel, metres above the mean level; shared, not copied
     */
    record Frame(int size, float[] slopes, float[] heights) {

        /** ∂h/∂x at texel (x, z), dimensionless. */
        float slopeX(int x, int z) {
            return slopes[2 * index(x, z)];
        }

        /** ∂h/∂z at texel (x, z), dimensionless. */
        float slopeZ(int x, int z) {
            return slopes[2 * index(x, z) + 1];
        }

        /** The height at texel (x, z), metres above the mean level. */
        float height(int x, int z) {
            return heights[index(x, z)];
        }

        private int index(int x, int z) {
            return Objects.checkIndex(z, size) * size + Objects.checkIndex(x, size);
        }
    }

    /**
     * Scales {@code h0} in place so the slopes' RMS over the frames is {@code targetRmsSlope} (Parseval, see the
     * class comment), then transforms every frame and measures what came out.
     */
    private RippleField(int size, int frames, double tileMetres, double periodSeconds, double[] h0,
            double[] cyclesPerPeriod, double targetRmsSlope) {
        this.size = size;
        this.frames = frames;
        this.tileMetres = tileMetres;
        this.periodSeconds = periodSeconds;
        this.h0 = h0;
        this.cyclesPerPeriod = cyclesPerPeriod;

        // 1. the amplitude, by Parseval: mean over texels of |field|² = Σ_k |coefficient|², averaged over frames
        double dk = 2 * Math.PI / tileMetres;
        double[] h = new double[2 * size * size];
        double sum = 0;
        for (int f = 0; f < frames; f++) {
            waveSpectrum(f / (double) frames, h);
            for (int r = 0; r < size; r++) {
                int n = frequency(r, size);
                for (int c = 0; c < size; c++) {
                    int m = frequency(c, size);
                    int i = r * size + c;
                    sum += dk * dk * (m * m + n * n) * (h[2 * i] * h[2 * i] + h[2 * i + 1] * h[2 * i + 1]);
                }
            }
        }
        double scale = targetRmsSlope / Math.sqrt(sum / frames);
        for (int i = 0; i < h0.length; i++) {
            h0[i] *= scale;
        }

        // 2. the frames, t = f · period / frames
        this.layers = FftThreads.pinned(() -> {
            FloatFFT_2D fft = new FloatFFT_2D(size, size);
            List<Frame> made = new ArrayList<>(frames);
            for (int f = 0; f < frames; f++) {
                made.add(transform(f / (double) frames, fft));
            }
            return List.copyOf(made);
        });

        // 3. what they hold
        double slopeSum = 0;
        double heightSum = 0;
        for (Frame frame : layers) {
            for (float s : frame.slopes()) {
                slopeSum += (double) s * s;
            }
            for (float v : frame.heights()) {
                heightSum += (double) v * v;
            }
        }
        double texels = (double) frames * size * size;
        this.rmsSlope = Math.sqrt(slopeSum / texels);
        this.rmsHeight = Math.sqrt(heightSum / texels);
    }

    /**
     * Synthesises the ripple tile (see the class comment).
     *
     * @param size                 texels per side, a power of two in [{@value #MIN_SIZE}, {@value #MAX_SIZE}]
     * @param frames               layers, ≥ 1; frame f is the field at t = f · periodSeconds / frames
     * @param tileMetres           side of the tile, metres, &gt; 0
     * @param periodSeconds        loop period, seconds, &gt; 0
     * @param windSpeed            wind speed V, m/s, &gt; 0
     * @param windDirectionDegrees where the wind blows towards, degrees clockwise from north seen from above
     *                             (0 towards −Z, 90 towards +X), any finite angle
     * @param rmsSlope             target √(mean of sx² + sz²) over all texels and frames, &gt; 0; meant to be
     *                             Cox and Munk's √(0.003 + 0.00512 V), possibly scaled
     * @param seed                 seed of the {@link Random} that draws the wave amplitudes
     * @throws IllegalArgumentException naming the argument and its valid range when one is out of range, or
     *                                  naming windSpeed when the wind raises no wave the tile resolves
     */
    static RippleField synthesize(int size, int frames, double tileMetres, double periodSeconds, double windSpeed,
            double windDirectionDegrees, double rmsSlope, long seed) {
        if (size < MIN_SIZE || size > MAX_SIZE || Integer.bitCount(size) != 1) {
            throw new IllegalArgumentException(
                    "size must be a power of two in [" + MIN_SIZE + ", " + MAX_SIZE + "], got " + size);
        }
        if (frames < 1) {
            throw new IllegalArgumentException("frames must be ≥ 1, got " + frames);
        }
        requirePositive("tileMetres", tileMetres);
        requirePositive("periodSeconds", periodSeconds);
        requirePositive("windSpeed", windSpeed);
        if (!Double.isFinite(windDirectionDegrees)) {
            throw new IllegalArgumentException(
                    "windDirectionDegrees must be a finite angle, got " + windDirectionDegrees);
        }
        requirePositive("rmsSlope", rmsSlope);

        double[] h0 = phillipsAmplitudes(size, tileMetres, windSpeed, windDirectionDegrees, seed);
        // Only the shape matters here (the constructor rescales); bring the largest amplitude to 1 so that the
        // squared amplitudes of a faint spectrum (a weak wind on a fine tile) do not underflow in the Parseval sum.
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
        return new RippleField(size, frames, tileMetres, periodSeconds, h0, cycles, rmsSlope);
    }

    private static void requirePositive(String name, double value) {
        if (!(value > 0) || !Double.isFinite(value)) {
            throw new IllegalArgumentException(name + " must be finite and > 0, got " + value);
        }
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
        Random random = new Random(seed);
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

    /**
     * Writes h(k, t) = h0(k) e^{−iωt} + conj(h0(−k)) e^{+iωt} for every lattice index into {@code out} (real and
     * imaginary interleaved), at {@code periods} = t / period. The phase ω t = 2π · cycles · t / period is reduced
     * to its fraction of a turn first, so whole periods give exactly the same phases.
     */
    private void waveSpectrum(double periods, double[] out) {
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

    /** The slopes and heights at {@code periods} = t / period, by two inverse transforms (see the class comment). */
    private Frame transform(double periods, FloatFFT_2D fft) {
        double dk = 2 * Math.PI / tileMetres;
        double[] h = new double[2 * size * size];
        waveSpectrum(periods, h);
        float[] slopes = new float[2 * size * size];
        float[] complexHeights = new float[2 * size * size];
        for (int r = 0; r < size; r++) {
            double kz = dk * frequency(r, size);
            for (int c = 0; c < size; c++) {
                double kx = dk * frequency(c, size);
                int i = r * size + c;
                double hr = h[2 * i];
                double hi = h[2 * i + 1];
                // i kx h + i (i kz h) = (hr + i hi)(−kz + i kx): its transform is sx + i sz
                slopes[2 * i] = (float) (-kz * hr - kx * hi);
                slopes[2 * i + 1] = (float) (kx * hr - kz * hi);
                complexHeights[2 * i] = (float) hr;
                complexHeights[2 * i + 1] = (float) hi;
            }
        }
        fft.complexInverse(slopes, false);
        fft.complexInverse(complexHeights, false);
        float[] heights = new float[size * size];
        for (int i = 0; i < heights.length; i++) {
            heights[i] = complexHeights[2 * i]; // the imaginary part is 0 up to rounding: h(−k) = conj(h(k))
        }
        return new Frame(size, slopes, heights);
    }

    /**
     * The field at any time {@code seconds}, not only on the frame grid: the same waves, so
     * {@code fieldAt(f · periodSeconds / frames)} is frame f and {@code fieldAt(t + periodSeconds)} is
     * {@code fieldAt(t)}. For tests and tools; the renderer uses the frames.
     */
    Frame fieldAt(double seconds) {
        return FftThreads.pinned(() -> transform(seconds / periodSeconds, new FloatFFT_2D(size, size)));
    }

    /** Texels per side. */
    int size() {
        return size;
    }

    /** Layers in the loop. */
    int frames() {
        return frames;
    }

    /** Side of the tile, metres. */
    double tileMetres() {
        return tileMetres;
    }

    /** Loop period, seconds. */
    double periodSeconds() {
        return periodSeconds;
    }

    /** Frame {@code frame}: the field at t = frame · periodSeconds / frames. */
    Frame frame(int frame) {
        return layers.get(frame);
    }

    /** ∂h/∂x at texel (x, z) of a frame, dimensionless. */
    float slopeX(int frame, int x, int z) {
        return layers.get(frame).slopeX(x, z);
    }

    /** ∂h/∂z at texel (x, z) of a frame, dimensionless. */
    float slopeZ(int frame, int x, int z) {
        return layers.get(frame).slopeZ(x, z);
    }

    /** √(mean of sx² + sz²) measured over all texels and frames: the requested value up to float rounding. */
    double rmsSlope() {
        return rmsSlope;
    }

    /** √(mean of h²) over all texels and frames, metres: the height channel of {@link #texels} spans ±3 of it. */
    double rmsHeight() {
        return rmsHeight;
    }

    /**
     * The frames as RGBA8 texels for a texture array, one {@code 4 · size²} byte array per frame, rows z = 0..,
     * x fastest: R = 128 + 127 · clamp(sx / slopeScale, −1, 1), G likewise for sz, B likewise for
     * h / ({@value #HEIGHT_RANGE_IN_RMS} · {@link #rmsHeight()}), A = 255, each rounded to the nearest integer. The
     * shader decodes s = (byte − 128) / 127 · slopeScale, within 0.5 / 127 · slopeScale of the float.
     *
     * @param slopeScale the slope that maps to 255 (its negative to 1), &gt; 0: a few times {@link #rmsSlope()}
     *                   keeps clamping rare and the steps fine
     */
    List<byte[]> texels(float slopeScale) {
        if (!(slopeScale > 0) || !Float.isFinite(slopeScale)) {
            throw new IllegalArgumentException("slopeScale must be finite and > 0, got " + slopeScale);
        }
        double heightScale = HEIGHT_RANGE_IN_RMS * rmsHeight;
        List<byte[]> out = new ArrayList<>(frames);
        for (Frame frame : layers) {
            byte[] rgba = new byte[4 * size * size];
            for (int i = 0; i < size * size; i++) {
                rgba[4 * i] = unorm8(frame.slopes()[2 * i] / slopeScale);
                rgba[4 * i + 1] = unorm8(frame.slopes()[2 * i + 1] / slopeScale);
                rgba[4 * i + 2] = unorm8(frame.heights()[i] / heightScale);
                rgba[4 * i + 3] = (byte) 255;
            }
            out.add(rgba);
        }
        return out;
    }

    /** 128 + 127 · clamp(v, −1, 1), rounded: 1 .. 255 with 128 for 0. */
    private static byte unorm8(double v) {
        return (byte) Math.round(128 + 127 * Math.max(-1, Math.min(1, v)));
    }
}

package org.openworld.engine.water;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.jtransforms.fft.FloatFFT_2D;
import org.openworld.engine.core.FftThreads;

/**
 * The water's ripples: a periodic tile of wind-driven waves that loops in time, synthesised once on the CPU as
 * Tessendorf's FFT ocean (J. Tessendorf, "Simulating Ocean Water", SIGGRAPH course notes 2001) and handed to the
 * shader as {@link #frames()} layers of surface slopes. The derivation, step by step, is in
 * {@code docs/water.md}, section "The ripples, derived".
 *
 * <p><b>What it does.</b> The waves come from {@link RippleSpectrum}: Phillips' wind-sea spectrum on the tile's
 * lattice of wave vectors, each wave moving by the deep-water dispersion ω² = g k quantised to whole cycles per
 * period, so that frame f, the field at t = f · period / frames, loops seamlessly. This class makes the frames:
 * <ul>
 *   <li>the slopes by spectral derivative, the transforms of i kx h(k, t) and i kz h(k, t): exact derivatives, none
 *       of a finite difference's blur. Both are real, so one complex inverse transform of h (i kx − kz) carries the
 *       pair as sx + i sz; the height takes a second;</li>
 *   <li>the amplitude, fixed before any transform by Parseval's theorem so that the slopes' RMS over all texels and
 *       frames is the caller's {@code rmsSlope}, meant to be Cox and Munk's clean-surface
 *       √(0.003 + 0.00512 V) for a wind of V m/s (JOSA 44, 1954), possibly scaled; this class honours whatever it is
 *       given;</li>
 *   <li>the texels: the slopes of two successive frames packed into RGBA8 ({@link #texels}), so the shader blends
 *       between frames with one texture read.</li>
 * </ul>
 *
 * <p><b>Cost.</b> At start-up, O(F · N² log N) for F frames of N² texels: per frame, N² sines and cosines for the
 * wave phases (twice: once for the amplitude, once for the frame) and two complex N² transforms. Nothing per
 * rendered frame: the shader only looks the slopes up. 128² texels × 32 frames take 0.10 to 0.15 s (0.26 s on a
 * cold JVM) on a 2-core machine, plus 11 ms for {@link #texels}, and hold 6 MiB of floats. JTransforms' thread count
 * is pinned by {@link FftThreads} during the transforms, as for the terrain and the clouds, so the result cannot
 * depend on the machine; below 256² texels (its threshold for 2D transforms) JTransforms runs on the calling thread
 * anyway.
 *
 * <p><b>Limits.</b> The tile repeats (the shader samples it at two scales to hide that), no wave is longer than the
 * tile or shorter than two texels; the waves are linear: crests as round as troughs, nothing steepens, breaks or
 * foams (Tessendorf's horizontal "choppy" displacement is not included); the spectrum's own limits are
 * {@link RippleSpectrum}'s.
 */
final class RippleField {

    /** Smallest tile side, texels: fewer leaves hardly any waves between the mean and the Nyquist frequency. */
    static final int MIN_SIZE = 8;

    /** Largest tile side, texels: 4096² floats are 64 MiB per layer, already far beyond a ripple texture. */
    static final int MAX_SIZE = 4096;

    private final int frames;
    private final double tileMetres;
    private final double periodSeconds;
    /** The waves, scaled to the target slope. */
    private final RippleSpectrum spectrum;
    private final List<Frame> layers;
    private final double rmsSlope;

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
     * Scales the spectrum in place so the slopes' RMS over the frames is {@code targetRmsSlope} (Parseval, see
     * {@link RippleSpectrum#meanSquareSlope}), then transforms every frame and measures what came out.
     */
    private RippleField(int frames, double tileMetres, double periodSeconds, RippleSpectrum spectrum,
            double targetRmsSlope) {
        this.frames = frames;
        this.tileMetres = tileMetres;
        this.periodSeconds = periodSeconds;
        this.spectrum = spectrum;

        // 1. the amplitude, by Parseval: mean over texels of |field|² = Σ_k |coefficient|², averaged over frames
        spectrum.scale(targetRmsSlope / Math.sqrt(spectrum.meanSquareSlope(frames)));

        // 2. the frames, t = f · period / frames
        int size = spectrum.size();
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
        for (Frame frame : layers) {
            for (float s : frame.slopes()) {
                slopeSum += (double) s * s;
            }
        }
        this.rmsSlope = Math.sqrt(slopeSum / ((double) frames * size * size));
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
     * @param seed                 the world seed ({@code engine.seed}): the wave amplitudes' random stream derives
     *                             from it, so one seed gives one field and another seed another
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
        RippleSpectrum spectrum = RippleSpectrum.of(size, tileMetres, periodSeconds, windSpeed, windDirectionDegrees,
                seed);
        return new RippleField(frames, tileMetres, periodSeconds, spectrum, rmsSlope);
    }

    private static void requirePositive(String name, double value) {
        if (!(value > 0) || !Double.isFinite(value)) {
            throw new IllegalArgumentException(name + " must be finite and > 0, got " + value);
        }
    }

    /** The slopes and heights at {@code periods} = t / period, by two inverse transforms (see the class comment). */
    private Frame transform(double periods, FloatFFT_2D fft) {
        int size = spectrum.size();
        double dk = spectrum.dk();
        double[] h = new double[2 * size * size];
        spectrum.at(periods, h);
        float[] slopes = new float[2 * size * size];
        float[] complexHeights = new float[2 * size * size];
        for (int r = 0; r < size; r++) {
            double kz = dk * RippleSpectrum.frequency(r, size);
            for (int c = 0; c < size; c++) {
                double kx = dk * RippleSpectrum.frequency(c, size);
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
        // JTransforms' unscaled inverse, a[x] = Σ A[k] e^{+2πi k x / N}: the synthesis sum h(x) = Σ h(k) e^{i k·x}
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
        int size = spectrum.size();
        return FftThreads.pinned(() -> transform(seconds / periodSeconds, new FloatFFT_2D(size, size)));
    }

    /** Texels per side. */
    int size() {
        return spectrum.size();
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

    /**
     * The frames as RGBA8 texels for a texture array, one {@code 4 · size²} byte array per frame f, rows z = 0..,
     * x fastest: R = 128 + 127 · clamp(sx / slopeScale, −1, 1) and G likewise for sz, both of frame f; B and A the
     * same of frame f + 1 (frame 0 after the last: the loop closes), each rounded to the nearest integer. The shader
     * decodes s = (byte − 128) / 127 · slopeScale, within 0.5 / 127 · slopeScale of the float, and blends frame f
     * into f + 1 from a single texture read, where a texel of one frame would take two.
     *
     * @param slopeScale the slope that maps to 255 (its negative to 1), &gt; 0: a few times {@link #rmsSlope()}
     *                   keeps clamping rare and the steps fine
     */
    List<byte[]> texels(float slopeScale) {
        if (!(slopeScale > 0) || !Float.isFinite(slopeScale)) {
            throw new IllegalArgumentException("slopeScale must be finite and > 0, got " + slopeScale);
        }
        int size = spectrum.size();
        List<byte[]> out = new ArrayList<>(frames);
        for (int f = 0; f < frames; f++) {
            float[] now = layers.get(f).slopes();
            float[] next = layers.get((f + 1) % frames).slopes();
            byte[] rgba = new byte[4 * size * size];
            for (int i = 0; i < size * size; i++) {
                rgba[4 * i] = unorm8(now[2 * i] / slopeScale);
                rgba[4 * i + 1] = unorm8(now[2 * i + 1] / slopeScale);
                rgba[4 * i + 2] = unorm8(next[2 * i] / slopeScale);
                rgba[4 * i + 3] = unorm8(next[2 * i + 1] / slopeScale);
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

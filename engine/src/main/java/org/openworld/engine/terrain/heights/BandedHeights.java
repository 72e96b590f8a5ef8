package org.openworld.engine.terrain.heights;

import java.util.SplittableRandom;
import java.util.function.DoubleBinaryOperator;
import java.util.stream.IntStream;
import org.openworld.engine.tectonics.RangeField;

/**
 * The unbounded world's heights, made per level: the 1/ω^β spectrum of {@link SpectralSynthesis} split
 * into octave bands ({@link OctaveBand}), each a small periodic tile, so that level L of the pyramid is the sum of the
 * bands L and coarser, computed directly at L's spacing for any window, with no full-resolution map anywhere.
 *
 * <h2>Bands and levels</h2>
 * Level L has samples {@code d_L = 2^L · terrain.spacing} apart. Band k holds the frequencies
 * {@code 1/(4 d_k) ≤ ω < 1/(2 d_k)} (wavelengths 2 d_k to 4 d_k, within the settings' cut-offs), so the bands tile
 * the spectrum without overlap and level L, the sum of the bands k ≥ L, holds exactly the frequencies below its own
 * Nyquist frequency 1/(2 d_L): sampled at d_L it does not alias, and level L + 1 is level L with its finest octave
 * taken out, its band-limited version. With the defaults (2 m, wavelengths 4 m to 2048 m) there are 9 bands:
 * 4–8 m, 8–16 m, ... 1024–2048 m. Heights are {@code h = relief · (Σ bands / (6σ) + 0.5 − seaFraction)}, σ the
 * standard deviation of the whole sum (from the spectra, by Parseval): like the periodic tile's normalisation, whose
 * relief spans its lowest to highest sample, with the range taken as ±3σ (a few per mille of the ground lie beyond).
 *
 * <h2>Never repeating</h2>
 * Band k repeats on its own lattice of side {@code P_k = 512 · d_k/2} (131 km for the 1–2 km band, 512 m for the
 * 4–8 m band), turned by its own random angle and shifted by its own random offset. The sum repeats only where a
 * displacement T is, for every band at once, within a small fraction ε of that band's shortest wavelength 2 d_k of
 * one of its lattice points. Counting from the coarsest band: a disc of radius R holds π R² / P² of its lattice
 * points, and each other band matches at one of them with probability π (ε · 2 d_k)² / P_k² = π (ε/128)², which is
 * 1.9·10⁻⁶ for ε = 0.1. For R = 10 000 km and the defaults' 9 bands: π · 10¹⁴ / 1.7·10¹⁰ = 1.8·10⁴ candidates times
 * (1.9·10⁻⁶)⁸ = 1.7·10⁻⁴⁶ gives 3·10⁻⁴² expected repeats: none within 10 000 km. Single bands do come back: 131 km
 * along the coarsest band's lattice its shapes return (about 80 % of the variance for β = 2.2), under other finer
 * bands.
 *
 * <h2>Determinism</h2>
 * Each band's tile is made once, from the seed, when the world is made; a height is then a fixed sum, coarsest band
 * first, of fixed double expressions of the position: the same bits whatever was asked before, in what order or on
 * which thread. Positions are doubles (or integer sample indices times the spacing), exact to nanometres at
 * thousands of kilometres.
 *
 * <h2>Cost</h2>
 * Making the world: one 512² inverse FFT per band, 9 MiB of tiles for the defaults (1 MiB a band). A height of
 * level L: one 16-sample B-spline per band k ≥ L.
 */
public final class BandedHeights implements UniformHeights {

    /** The relief spans this many standard deviations of the summed bands (±3σ). */
    static final double RELIEF_SIGMAS = 6;

    /** Distinguishes the bands' random stream from the other users of the world seed. */
    private static final long STREAM = 0xBA4D_5EED_0C7A_0002L;

    /** Below this many samples per side a window's rows are filled on the calling thread. */
    private static final int PARALLEL_MIN_SIZE = 128;

    /** Random places at which {@link #levelErrors} measures each level's error. */
    static final int ERROR_SAMPLES = 20_000;
    /** The measured largest error is raised by this margin: the world's largest lies beyond any finite sample. */
    public static final double ERROR_MARGIN = 1.25;

    private final OctaveBand[] bands;
    private final double spacing;
    private final double metresPerUnit;
    private final double base;
    private final double reach;
    /** Ranges and plains over the bands (terrain.ranges), or null for the bands alone. */
    private final RangeField ranges;

    /** The world of these settings (spacing, relief, sea fraction, β, cut-offs) and seed; terrain.size is unused. */
    public BandedHeights(TerrainSettings s, int seed) {
        this.spacing = s.spacing();
        SplittableRandom random = new SplittableRandom(seed ^ STREAM);
        int count = 0;
        while (Math.scalb(2 * spacing, count) < s.maxWavelength()) {
            count++; // band k has content only if its shortest wavelength 2 d_k lies below the longest kept
        }
        bands = new OctaveBand[count];
        double variance = 0;
        for (int k = 0; k < count; k++) {
            bands[k] = OctaveBand.make(k, spacing, s.beta(), s.minWavelength(), s.maxWavelength(), random);
            variance += bands[k] == null ? 0 : bands[k].variance();
        }
        metresPerUnit = s.relief() / (RELIEF_SIGMAS * Math.sqrt(variance));
        base = s.relief() * (0.5 - s.seaFraction());
        double r = 0;
        for (OctaveBand band : bands) {
            r += band == null ? 0 : metresPerUnit * band.bound();
        }
        reach = r;
        ranges = s.ranges() ? new RangeField(seed, s.relief()) : null;
    }

    /** No height of any level lies below this, metres: the mean less every band's largest magnitude. */
    @Override
    public double lowest() {
        return base - reach - (ranges == null ? 0 : ranges.drop());
    }

    /** No height of any level lies above this, metres. */
    @Override
    public double highest() {
        return base + reach;
    }

    /**
     * How far the surface drawn from each level's samples lies from the finest heights, metres, for levels
     * 0 .. count − 1 (0 for level 0): {@link #surface} of level L against level 0, the largest difference at
     * {@value #ERROR_SAMPLES} random places (the same places for every seed), raised by {@value #ERROR_MARGIN}.
     * The world is statistically the same everywhere, so one figure per level stands for every node of that level;
     * it is an estimate, not a bound: somewhere in an unbounded world a larger error exists.
     *
     * @param count 1 .. {@link #levels()}
     */
    @Override
    public float[] levelErrors(int count) {
        checkLevel(count - 1);
        float[] errors = new float[count];
        SplittableRandom random = new SplittableRandom(STREAM);
        double[] xs = new double[ERROR_SAMPLES];
        double[] zs = new double[ERROR_SAMPLES];
        double span = Math.scalb(spacing, bands.length) * OctaveBand.TILE;
        for (int i = 0; i < ERROR_SAMPLES; i++) {
            xs[i] = (random.nextDouble() - 0.5) * span;
            zs[i] = (random.nextDouble() - 0.5) * span;
        }
        IntStream.range(1, count).parallel().forEach(level -> {
            double worst = 0;
            for (int i = 0; i < ERROR_SAMPLES; i++) {
                worst = Math.max(worst, Math.abs(height(0, xs[i], zs[i]) - surface(level, xs[i], zs[i])));
            }
            errors[level] = (float) (ERROR_MARGIN * worst);
        });
        return errors;
    }

    /** The number of bands, and of levels with a band of their own: level L holds bands L .. levels() − 1. */
    @Override
    public int levels() {
        return bands.length;
    }

    /** Metres between the samples of a level: 2^level · terrain.spacing. */
    @Override
    public double spacing(int level) {
        return Math.scalb(spacing, level);
    }

    /** Height of a level at (x, z), metres: the mean height plus the bands {@code level} and coarser. */
    @Override
    public double height(int level, double x, double z) {
        checkLevel(level);
        double h = ranges == null ? base : 0;
        for (int k = bands.length - 1; k >= level; k--) {
            h += band(k, x, z);
        }
        return ranges == null ? h : base + ranges.shape(x, z, h);
    }

    /** Band k's share of the height at (x, z), metres (0 for a band the cut-offs leave empty). */
    public double band(int k, double x, double z) {
        checkLevel(k);
        OctaveBand band = bands[k];
        return band == null ? 0 : metresPerUnit * band.value(x, z);
    }

    /**
     * A window of level {@code level}: n × n heights, row-major, sample (i, j) at world
     * ((ix0 + i) · d, (iz0 + j) · d) for d = {@link #spacing(int)}.
     */
    @Override
    public float[] level(int level, long ix0, long iz0, int n) {
        return window(level, ix0, iz0, n, (x, z) -> height(level, x, z));
    }

    /** Band k's share of a window of level {@code level}'s samples, as {@link #level}. */
    public float[] band(int k, int level, long ix0, long iz0, int n) {
        checkLevel(k);
        return window(level, ix0, iz0, n, (x, z) -> band(k, x, z));
    }

    private float[] window(int level, long ix0, long iz0, int n, DoubleBinaryOperator height) {
        checkLevel(level);
        if (n < 1) {
            throw new IllegalArgumentException("a window needs at least one sample a side, got " + n);
        }
        double d = spacing(level);
        float[] h = new float[n * n];
        IntStream rows = IntStream.range(0, n);
        (n >= PARALLEL_MIN_SIZE ? rows.parallel() : rows).forEach(j -> {
            double z = (iz0 + j) * d;
            for (int i = 0; i < n; i++) {
                h[j * n + i] = (float) height.applyAsDouble((ix0 + i) * d, z);
            }
        });
        return h;
    }

    private void checkLevel(int level) {
        if (level < 0 || level >= bands.length) {
            throw new IllegalArgumentException("level " + level + " outside 0 .. " + (bands.length - 1));
        }
    }
}

package org.openworld.engine.terrain.material;

import java.util.stream.IntStream;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.HeightPyramid;
import org.openworld.engine.terrain.heights.TerrainSettings;

/**
 * Where snow lies (paper 2.2, figure 2b): each sample is snow with a probability that rises with its normalised
 * height, and a morphological opening and closing then turn the random speckle into patches with a ragged edge.
 * Made one way for every height source, over any window of samples ({@link #cover}): a sample's random draw is a
 * hash of its place, so a tile (one window, wrapped) and the unbounded world (a window per streamed block, with a
 * border: {@code stream.StreamedSnow}) make the same snow from the same heights, whatever the window.
 *
 * <ol>
 *   <li>The pyramid level with at most {@link #MAX_SIZE} samples per side is used (at the default 2 m spacing
 *       that is one snow sample per 2 m, on a 8192² map one per 8 m): finer snow cannot be seen from where its
 *       pattern matters, and the map stays quick to make and small to upload.</li>
 *   <li>Normalised height n = h / relief + seaFraction (0 at the lowest, 1 at the highest sample of the generated or
 *       imported map, the inverse of its normalisation); p(n) = clamp((n − snowBase) / (snowFull − snowBase), 0, 1);
 *       a sample is snow when a uniform number u is below p(n), u a hash of the world seed and the sample's index
 *       ({@link #uniform}: SplitMix64's finaliser), taken modulo the tile's side on a periodic tile so that its
 *       copies join; the same on any number of cores and in any window.</li>
 *   <li>Opening (erosion, then dilation) removes snow specks smaller than the structuring element; the closing
 *       after it (dilation, then erosion) fills bare pinholes inside snow fields. The element is a square of radius
 *       {@code snowMorphology} samples, applied as a line along x then along z: a square is separable, so each pass
 *       is a sliding count of snow samples in the window, whatever the radius.</li>
 * </ol>
 * The opening keeps only snow that fills a whole (2r+1)² square, which random snow of probability p does with
 * probability p^((2r+1)²): 0.9^25 = 0.07 for r = 2. So the closed snow fields lie where p is close to 1, just below
 * {@code snowFull}, and the band between {@code snowBase} and there becomes the ragged, speckled fringe of figure 2b.
 * Coverage wraps at the edges like the height map (periodic) or repeats its edge samples (imported). A window
 * cut from a larger map with a border of at least 4r samples holds, inside the border, what the whole map holds
 * there (what a sample becomes depends on the samples within 4r of it).
 *
 * <p>Cost: a hash and four sliding counts per sample, 0.6–1.8 s for the default 2048² tile on a loaded two-core
 * machine; on the CPU, so that {@code openworld heightmap} draws figure 2b without OpenGL.
 */
public final class SnowMap {

    /** Largest snow map side, samples: 2048² bytes, 4 MiB, made in a fraction of a second. */
    public static final int MAX_SIZE = 2048;

    /** The value of a snow sample in {@link #coverage()}; bare ground is 0. */
    public static final byte SNOW = (byte) 255;

    /** Distinguishes the snow's hash from the other users of the world seed (the synthesis, the bands). */
    private static final long STREAM = 0x5EED_5A0E_0000_0003L;

    /** Maps smaller than this many samples per side are processed on one thread. */
    private static final int PARALLEL_MIN_SIZE = 256;

    /** Columns per band of the vertical pass, samples: the band's running counts (512 bytes) stay in L1 cache. */
    private static final int BAND_WIDTH = 128;

    private final int size;
    private final double spacing;
    private final boolean periodic;
    private final byte[] coverage;

    /**
     * @param size     samples per side, a power of two
     * @param spacing  metres between samples
     * @param periodic whether lookups wrap (else clamp)
     * @param coverage {@code size²} bytes, 0 bare or {@link #SNOW}, row-major like a height map; kept, not copied
     */
    public SnowMap(int size, double spacing, boolean periodic, byte[] coverage) {
        if (size < 1 || Integer.bitCount(size) != 1) {
            throw new IllegalArgumentException("snow map size must be a power of two, got " + size);
        }
        if (coverage.length != size * size) {
            throw new IllegalArgumentException("a snow map of size " + size + " needs " + size * size
                    + " samples, got " + coverage.length);
        }
        this.size = size;
        this.spacing = spacing;
        this.periodic = periodic;
        this.coverage = coverage;
    }

    /** The snow map of a pyramid, from its first level no larger than {@link #MAX_SIZE}. */
    public static SnowMap generate(HeightPyramid pyramid, TerrainSettings s, int seed) {
        HeightMap map = pyramid.level(0);
        for (int k = 1; map.size() > MAX_SIZE; k++) {
            map = pyramid.level(k);
        }
        int n = map.size();
        byte[] snow = cover(map.heights(), n, 0, 0, map.periodic() ? n : 0, s, seed);
        return new SnowMap(n, map.spacing(), map.periodic(), snow);
    }

    /**
     * Steps 2 and 3 of the class comment over a window of heights: {@code side²} samples, row-major, the first
     * sample (ix0, iz0) of its level. Sample indices count modulo {@code period} (a periodic tile's side; 0 for an
     * imported tile or the unbounded world, which do not repeat). A window that is one whole period wraps its
     * filters, as its tile does; any other clamps them at its edges, and only what lies 4r or more inside them is
     * what a larger window would hold. Returns 0 (bare) or {@link #SNOW} per sample.
     */
    public static byte[] cover(float[] heights, int side, long ix0, long iz0, long period, TerrainSettings s,
                               int seed) {
        byte[] snow = new byte[side * side];
        long hashSeed = seed ^ STREAM;
        rows(side).forEach(z -> {
            for (int x = 0; x < side; x++) {
                int i = z * side + x;
                double u = uniform(hashSeed, index(ix0 + x, period), index(iz0 + z, period));
                if (u < probability(heights[i] / s.relief() + s.seaFraction(), s)) {
                    snow[i] = SNOW;
                }
            }
        });
        openAndClose(snow, side, s.snowMorphology(), period == side);
        return snow;
    }

    /** A sample index, modulo the period when there is one. */
    private static long index(long i, long period) {
        return period > 0 ? Math.floorMod(i, period) : i;
    }

    /** A uniform number in [0, 1) for a sample: its index and the seed, mixed (SplitMix64's finaliser). */
    private static double uniform(long seed, long ix, long iz) {
        long z = seed + ix * 0x9E37_79B9_7F4A_7C15L + iz * 0xC2B2_AE3D_27D4_EB4FL;
        z = (z ^ (z >>> 30)) * 0xBF58_476D_1CE4_E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D0_49BB_1331_11EBL;
        z ^= z >>> 31;
        return (z >>> 11) * 0x1.0p-53;
    }

    /**
     * Step 3 of the class comment on an n × n map of 0 / {@link #SNOW} samples, in place: the opening (erode,
     * dilate), then the closing (dilate, erode), with a square of radius r; wrapping or clamping at the edges. What
     * a sample becomes depends on the samples within 4r of it.
     */
    public static void openAndClose(byte[] snow, int n, int r, boolean wrap) {
        if (r <= 0) {
            return;
        }
        byte[] tmp = new byte[n * n];
        morph(snow, tmp, n, r, wrap, false);
        morph(tmp, snow, n, r, wrap, true);
        morph(snow, tmp, n, r, wrap, true);
        morph(tmp, snow, n, r, wrap, false);
    }

    /** p(n) = clamp((n − snowBase) / (snowFull − snowBase), 0, 1): the chance of snow at normalised height n. */
    public static double probability(double normalisedHeight, TerrainSettings s) {
        double p = (normalisedHeight - s.snowBase()) / (s.snowFull() - s.snowBase());
        return Math.max(0, Math.min(1, p));
    }

    /**
     * Dilation (snow where any sample of the square window is snow) or erosion (snow where every one is), as a
     * sliding count along x then along z.
     */
    private static void morph(byte[] in, byte[] out, int n, int r, boolean wrap, boolean dilate) {
        int window = 2 * r + 1;
        byte[] mid = new byte[n * n];
        // 1. along x, one row at a time
        rows(n).forEach(z -> {
            int row = z * n;
            int count = 0;
            for (int i = -r; i <= r; i++) {
                count += in[row + edge(i, n, wrap)] != 0 ? 1 : 0;
            }
            for (int x = 0; x < n; x++) {
                mid[row + x] = decide(count, window, dilate);
                count += (in[row + edge(x + r + 1, n, wrap)] != 0 ? 1 : 0)
                        - (in[row + edge(x - r, n, wrap)] != 0 ? 1 : 0);
            }
        });
        // 2. along z, one column band at a time: a running count per column, rows read in order
        int bands = Math.max(1, n / BAND_WIDTH);
        IntStream bandStream = IntStream.range(0, bands);
        (n >= PARALLEL_MIN_SIZE ? bandStream.parallel() : bandStream).forEach(b -> {
            int x0 = b * n / bands;
            int x1 = (b + 1) * n / bands;
            int[] count = new int[x1 - x0];
            for (int i = -r; i <= r; i++) {
                int row = edge(i, n, wrap) * n;
                for (int x = x0; x < x1; x++) {
                    count[x - x0] += mid[row + x] != 0 ? 1 : 0;
                }
            }
            for (int z = 0; z < n; z++) {
                int enter = edge(z + r + 1, n, wrap) * n;
                int leave = edge(z - r, n, wrap) * n;
                for (int x = x0; x < x1; x++) {
                    out[z * n + x] = decide(count[x - x0], window, dilate);
                    count[x - x0] += (mid[enter + x] != 0 ? 1 : 0) - (mid[leave + x] != 0 ? 1 : 0);
                }
            }
        });
    }

    private static byte decide(int count, int window, boolean dilate) {
        return (dilate ? count > 0 : count == window) ? SNOW : 0;
    }

    private static int edge(int i, int n, boolean wrap) {
        return wrap ? i & (n - 1) : Math.max(0, Math.min(n - 1, i));
    }

    private static IntStream rows(int n) {
        IntStream rows = IntStream.range(0, n);
        return n >= PARALLEL_MIN_SIZE ? rows.parallel() : rows;
    }

    /** Samples per side. */
    public int size() {
        return size;
    }

    /** Metres between samples. */
    public double spacing() {
        return spacing;
    }

    public boolean periodic() {
        return periodic;
    }

    /** 0 (bare) or {@link #SNOW} per sample, row-major; shared, not copied. */
    public byte[] coverage() {
        return coverage;
    }

    /** Whether sample (x, z) is snow, wrapped or clamped like a height map. */
    public boolean snowAt(int x, int z) {
        return coverage[edge(z, size, periodic) * size + edge(x, size, periodic)] != 0;
    }

    /** Fraction of samples that are snow, 0 to 1. */
    public double fraction() {
        long snow = 0;
        for (byte b : coverage) {
            snow += b != 0 ? 1 : 0;
        }
        return (double) snow / coverage.length;
    }
}

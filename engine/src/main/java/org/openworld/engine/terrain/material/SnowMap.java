package org.openworld.engine.terrain.material;

import java.util.SplittableRandom;
import java.util.stream.IntStream;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.HeightPyramid;
import org.openworld.engine.terrain.heights.TerrainSettings;

/**
 * Where snow lies (paper 2.2, figure 2b): each sample is snow with a probability that rises with its normalised
 * height, and a morphological opening and closing then turn the random speckle into patches with a ragged edge.
 *
 * <ol>
 *   <li>The pyramid level with at most {@link #MAX_SIZE} samples per side is used (at the default 2 m spacing
 *       that is one snow sample per 2 m, on a 8192² map one per 8 m): finer snow cannot be seen from where its
 *       pattern matters, and the map stays quick to make and small to upload.</li>
 *   <li>Normalised height n = h / relief + seaFraction (0 at the lowest, 1 at the highest sample of the generated or
 *       imported map, the inverse of its normalisation); p(n) = clamp((n − snowBase) / (snowFull − snowBase), 0, 1);
 *       a sample is snow when a uniform random number from a {@link SplittableRandom} (one per row, seeded in row
 *       order from the world seed, so the map is the same on any number of cores) is below p(n).</li>
 *   <li>Opening (erosion, then dilation) removes snow specks smaller than the structuring element; the closing
 *       after it (dilation, then erosion) fills bare pinholes inside snow fields. The element is a square of radius
 *       {@code snowMorphology} samples, applied as a line along x then along z: a square is separable, so each pass
 *       is a sliding count of snow samples in the window, whatever the radius.</li>
 * </ol>
 * The opening keeps only snow that fills a whole (2r+1)² square, which random snow of probability p does with
 * probability p^((2r+1)²): 0.9^25 = 0.07 for r = 2. So the closed snow fields lie where p is close to 1, just below
 * {@code snowFull}, and the band between {@code snowBase} and there becomes the ragged, speckled fringe of figure 2b.
 * Coverage wraps at the edges like the height map (periodic) or repeats its edge samples (imported).
 */
public final class SnowMap {

    /** Largest snow map side, samples: 2048² bytes, 4 MiB, made in a fraction of a second. */
    public static final int MAX_SIZE = 2048;

    /** The value of a snow sample in {@link #coverage()}; bare ground is 0. */
    public static final byte SNOW = (byte) 255;

    /** Distinguishes the snow map's random stream from the other users of the world seed (the synthesis). */
    private static final long STREAM = 0x5EED_5A0E_0000_0002L;

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
        byte[] snow = scatter(map, s, seed);
        boolean wrap = map.periodic();
        openAndClose(snow, n, s.snowMorphology(), wrap);
        return new SnowMap(n, map.spacing(), wrap, snow);
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

    /** Snow with probability p(n) per sample (step 2 of the class comment). */
    private static byte[] scatter(HeightMap map, TerrainSettings s, int seed) {
        int n = map.size();
        float[] h = map.heights();
        byte[] snow = new byte[n * n];
        SplittableRandom root = new SplittableRandom(seed ^ STREAM);
        long[] rowSeeds = new long[n];
        for (int z = 0; z < n; z++) {
            rowSeeds[z] = root.nextLong();
        }
        rows(n).forEach(z -> {
            SplittableRandom random = new SplittableRandom(rowSeeds[z]);
            for (int i = z * n; i < (z + 1) * n; i++) {
                double normalised = h[i] / s.relief() + s.seaFraction();
                if (random.nextDouble() < probability(normalised, s)) {
                    snow[i] = SNOW;
                }
            }
        });
        return snow;
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

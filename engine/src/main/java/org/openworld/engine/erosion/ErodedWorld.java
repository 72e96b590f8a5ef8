package org.openworld.engine.erosion;

import java.util.SplittableRandom;
import java.util.stream.IntStream;
import org.openworld.engine.drainage.Wetness;
import org.openworld.engine.terrain.heights.BandedHeights;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.heights.UniformHeights;

/**
 * The unbounded world eroded: each level from the routing level up is the bands' level plus a displacement made on a
 * fixed lattice of overlapping regions ({@link RegionErosion}) and blended with bilinear weights, a partition of
 * unity; the levels below add the routing level's displacement read bilinearly. The package comment has the
 * scheme and why. A height is a pure function of the level, the place and the seed: blocks made in any order, on any
 * thread, agree to the bit.
 */
public final class ErodedWorld implements UniformHeights {

    /** Regions' cores are this many samples of their level a side, on a lattice from sample 0. */
    static final int CORE = 128;
    /**
     * Samples on each side of a line between two cores where both regions weigh, the weights ramping linearly
     * from 1 to 0 across the 2 · OVERLAP: the seam between two regions' river networks is blended away.
     */
    static final int OVERLAP = 16;
    /** Samples of a region's support a side: its core and the overlap around it. */
    static final int SUPPORT = CORE + 2 * OVERLAP + 1;
    /** Regions kept per level: a default window (512² samples) needs 5² of them; the rest is lead. */
    static final int CACHED = 49;
    /** Random places near the origin at which the erosion's share of each level's error is measured. */
    static final int ERROR_SAMPLES = 4_000;
    /** Side of the square around the origin they lie in, m: a few regions of the routing level a side. */
    static final double ERROR_SPAN_M = 2_048;

    private final BandedHeights plain;
    private final RegionErosion erosion;
    private final RegionCache[] caches;
    private final int first;

    /** The eroded world of these settings over its bands. */
    public ErodedWorld(BandedHeights plain, TerrainSettings s) {
        this.plain = plain;
        first = Math.min(plain.levels() - 1, (int) Math.max(0,
                Math.round(Math.log(TileErosion.ROUTING_SPACING_M / plain.spacing(0)) / Math.log(2))));
        caches = new RegionCache[plain.levels()];
        for (int l = first; l < caches.length; l++) {
            caches[l] = new RegionCache(CACHED);
        }
        erosion = new RegionErosion(plain, this, s.erosionTalus(), s.relief());
    }

    /** The unbounded world of these settings: eroded with {@code terrain.erosion}, the bands alone without. */
    public static UniformHeights unbounded(TerrainSettings s, int seed) {
        BandedHeights bands = new BandedHeights(s, seed);
        return s.erosion() ? new ErodedWorld(bands, s) : bands;
    }

    /** The level the rivers are first routed on: the finest with a displacement of its own. */
    public int routingLevel() {
        return first;
    }

    @Override
    public int levels() {
        return plain.levels();
    }

    @Override
    public double spacing(int level) {
        return plain.spacing(level);
    }

    @Override
    public double lowest() {
        return plain.lowest();
    }

    @Override
    public double highest() {
        return plain.highest();
    }

    @Override
    public double height(int level, double x, double z) {
        int k = Math.max(level, first);
        double d = spacing(k);
        long i = (long) Math.floor(x / d);
        long j = (long) Math.floor(z / d);
        float[][] w = blend(k, i, j, 2, 2);
        return clamp((float) plain.height(level, x, z) + bilinear(w[0], 2, 0, 0, x / d - i, z / d - j));
    }

    @Override
    public float[] level(int level, long ix0, long iz0, int n) {
        float[] h = plain.level(level, ix0, iz0, n);
        int k = Math.max(level, first);
        int shift = k - level;
        long i0 = ix0 >> shift;
        long j0 = iz0 >> shift;
        int m = (int) (((ix0 + n - 1) >> shift) - i0) + 2;
        int mz = (int) (((iz0 + n - 1) >> shift) - j0) + 2;
        float[][] w = blend(k, i0, j0, m, mz);
        double d = spacing(level);
        double dk = spacing(k);
        for (int j = 0; j < n; j++) {
            double gz = (iz0 + j) * d / dk;
            for (int i = 0; i < n; i++) {
                double gx = (ix0 + i) * d / dk;
                long ci = (long) Math.floor(gx);
                long cj = (long) Math.floor(gz);
                double delta = bilinear(w[0], m, (int) (ci - i0), (int) (cj - j0), gx - ci, gz - cj);
                h[j * n + i] = clamp(h[j * n + i] + delta);
            }
        }
        return h;
    }

    /**
     * The drainage area reaching (x, z) on the routing level, m²: what the eroded rivers gathered, coarse levels'
     * rivers included (read bilinearly between samples).
     */
    public double drainageArea(double x, double z) {
        double d = spacing(first);
        long i = (long) Math.floor(x / d);
        long j = (long) Math.floor(z / d);
        return bilinear(blend(first, i, j, 2, 2)[1], 2, 0, 0, x / d - i, z / d - j);
    }

    /**
     * How wet each place is ({@link Wetness}): the routing level's drainage area, and its slope by central
     * differences one sample either side; the sea is wet. Read from the regions the streamed blocks were made of;
     * a place far from every window makes its regions on the asking thread (a region's cost).
     */
    public Wetness wetness() {
        double d = spacing(first);
        return Wetness.of(this::drainageArea, (x, z) -> {
            if (height(first, x, z) <= 0) {
                return 1;
            }
            double sx = (height(first, x + d, z) - height(first, x - d, z)) / (2 * d);
            double sz = (height(first, x, z + d) - height(first, x, z - d)) / (2 * d);
            return Wetness.index(drainageArea(x, z), d, Math.hypot(sx, sz));
        });
    }

    /**
     * The plain bands' level errors ({@link BandedHeights#levelErrors}) plus what erosion adds to them: the largest
     * difference, at {@value #ERROR_SAMPLES} places within {@value #ERROR_SPAN_M} m of the origin, between the
     * displacement level 0 carries and the one level L's surface draws, raised by {@link BandedHeights#ERROR_MARGIN}.
     * By the triangle inequality the sum bounds the eroded surface's error wherever both parts hold.
     */
    @Override
    public float[] levelErrors(int count) {
        float[] errors = plain.levelErrors(count);
        SplittableRandom random = new SplittableRandom(count);
        double[] xs = new double[ERROR_SAMPLES];
        double[] zs = new double[ERROR_SAMPLES];
        for (int i = 0; i < ERROR_SAMPLES; i++) {
            xs[i] = (random.nextDouble() - 0.5) * ERROR_SPAN_M;
            zs[i] = (random.nextDouble() - 0.5) * ERROR_SPAN_M;
        }
        IntStream.range(1, count).forEach(level -> { // on this thread: see RegionErosion#bands
            double worst = 0;
            for (int i = 0; i < ERROR_SAMPLES; i++) {
                double eroded = height(0, xs[i], zs[i]) - surface(level, xs[i], zs[i]);
                double bands = plain.height(0, xs[i], zs[i]) - plain.surface(level, xs[i], zs[i]);
                worst = Math.max(worst, Math.abs(eroded - bands));
            }
            errors[level] += (float) (BandedHeights.ERROR_MARGIN * worst);
        });
        return errors;
    }

    /** Regions held now, over all levels (tests: the memory stays bounded). */
    int regionsHeld() {
        int held = 0;
        for (int l = first; l < caches.length; l++) {
            held += caches[l].size();
        }
        return held;
    }

    /**
     * The blended displacement and drainage area of level {@code level} (≥ the routing level) at its samples
     * (i0 + i, j0 + j), {@code w × h} of them: [0] the displacement, m, [1] the area, m². Each sample is the same
     * expression of its own index whatever the window, so windows agree where they overlap.
     */
    float[][] blend(int level, long i0, long j0, int w, int h) {
        float[][] out = {new float[w * h], new float[w * h]};
        long rx0 = Math.floorDiv(i0, CORE) - 1;
        long rz0 = Math.floorDiv(j0, CORE) - 1;
        int rw = (int) (Math.floorDiv(i0 + w - 1, CORE) - rx0) + 2;
        int rh = (int) (Math.floorDiv(j0 + h - 1, CORE) - rz0) + 2;
        Region[] held = new Region[rw * rh]; // made on this thread: see RegionErosion#bands
        long[] rx = new long[2];
        long[] rz = new long[2];
        double[] wx = new double[2];
        double[] wz = new double[2];
        for (int j = 0; j < h; j++) {
            int nz = weights(j0 + j, rz, wz);
            for (int i = 0; i < w; i++) {
                int nx = weights(i0 + i, rx, wx);
                double delta = 0;
                double area = 0;
                for (int b = 0; b < nz; b++) {
                    for (int a = 0; a < nx; a++) {
                        int slot = (int) (rz[b] - rz0) * rw + (int) (rx[a] - rx0);
                        if (held[slot] == null) {
                            held[slot] = region(level, rx[a], rz[b]);
                        }
                        // the sample's place in the region, whose support starts OVERLAP before its core
                        int at = (int) (j0 + j - rz[b] * CORE + OVERLAP) * SUPPORT
                                + (int) (i0 + i - rx[a] * CORE + OVERLAP);
                        double weight = wx[a] * wz[b];
                        delta += weight * held[slot].delta()[at];
                        area += weight * held[slot].area()[at];
                    }
                }
                out[0][j * w + i] = (float) delta;
                out[1][j * w + i] = (float) area;
            }
        }
        return out;
    }

    /**
     * The regions that weigh on sample {@code i} along one axis and their weights, which sum to 1: one region in
     * the middle of its core, two within {@link #OVERLAP} of a line between cores. Returns how many.
     */
    static int weights(long i, long[] regions, double[] weights) {
        long r = Math.floorDiv(i, CORE);
        long t = i - r * CORE;
        regions[0] = r;
        if (t < OVERLAP) { // near the line with the core before
            weights[0] = (t + OVERLAP) / (2.0 * OVERLAP);
            regions[1] = r - 1;
            weights[1] = 1 - weights[0];
            return 2;
        }
        if (t > CORE - OVERLAP) { // near the line with the core after
            weights[1] = (t - (CORE - OVERLAP)) / (2.0 * OVERLAP);
            regions[1] = r + 1;
            weights[0] = 1 - weights[1];
            return 2;
        }
        weights[0] = 1;
        return 1;
    }

    private Region region(int level, long rx, long rz) {
        return caches[level].get(rx, rz, () -> erosion.erode(level, rx, rz));
    }

    /** Values {@code w} wide read bilinearly at (i + fx, j + fz). */
    static double bilinear(float[] v, int w, int i, int j, double fx, double fz) {
        int at = j * w + i;
        double top = v[at] * (1 - fx) + v[at + 1] * fx;
        double bottom = v[at + w] * (1 - fx) + v[at + w + 1] * fx;
        return top * (1 - fz) + bottom * fz;
    }

    /** Keeps a height within the world's stated bounds, which the level choice's boxes rely on. */
    private float clamp(double h) {
        return (float) Math.max(lowest(), Math.min(highest(), h));
    }
}

package org.openworld.engine.terrain.heights;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.IntStream;

/**
 * The height map at every power-of-two resolution (paper 2.5): level 0 is the map itself, level k+1 is level k
 * low-pass filtered with a Gaussian and then decimated by two, so it holds no detail finer than its own sample
 * spacing ({@code spacing · 2^k}) and a patch drawn at level k shows heights, not aliases. Geomipmapping samples
 * level L for a patch of level L.
 *
 * <p>{@link #build} filters with the 5-tap binomial kernel (1 4 6 4 1)/16 along x and then z. It is the binomial
 * distribution B(4, ½) around the centre, variance 4 · ½ · ½ = 1, so it approximates a Gaussian of σ = 1 sample of
 * the finer level; its frequency response is cos⁴(πf) (f in cycles per sample), 1/4 at the new Nyquist frequency
 * f = 1/4 and 0 at the old one, so what would alias after keeping every second sample is mostly gone. Periodic maps
 * wrap at the edges, imported ones repeat their edge samples.
 *
 * <p>As a {@link HeightSource} (the generated tile's and the imported map's) its levels are the pyramid's, each
 * tile centred on the origin, so world sample (i, j) of level L is texel (i + n_L/2, j + n_L/2) of a level n_L a
 * side.
 */
public final class HeightPyramid implements HeightSource {

    /** Binomial weights 1/16, 4/16, 6/16 of the 5-tap kernel: exact in binary, so no rounding in the weights. */
    private static final float W0 = 6f / 16;
    private static final float W1 = 4f / 16;
    private static final float W2 = 1f / 16;

    /** Levels smaller than this many samples per side are filtered on one thread: forking costs more. */
    private static final int PARALLEL_MIN_SIZE = 256;

    private final List<HeightMap> levels;

    /** @param levels level 0 first; each half the size and twice the spacing of the one before */
    public HeightPyramid(List<HeightMap> levels) {
        for (int k = 1; k < levels.size(); k++) {
            if (levels.get(k).size() * 2 != levels.get(k - 1).size()) {
                throw new IllegalArgumentException("pyramid level " + k + " must be half the size of level " + (k - 1));
            }
        }
        this.levels = List.copyOf(levels);
    }

    /**
     * The pyramid of a map down to 1×1: level k+1 is level k filtered with the binomial kernel and decimated by two
     * (even samples kept), its spacing twice as large. Rows are filtered in parallel on large levels.
     */
    public static HeightPyramid build(HeightMap base) {
        List<HeightMap> levels = new ArrayList<>();
        levels.add(base);
        HeightMap level = base;
        while (level.size() > 1) {
            level = halve(level);
            levels.add(level);
        }
        return new HeightPyramid(levels);
    }

    /** One level down: filter along x keeping even columns, then along z keeping even rows. */
    private static HeightMap halve(HeightMap fine) {
        int n = fine.size();
        int half = n / 2;
        float[] in = fine.heights();
        boolean wrap = fine.periodic();
        // 1. along x: n rows of half samples
        float[] rows = new float[n * half];
        rows(n).forEach(z -> {
            int row = z * n;
            for (int x = 0; x < half; x++) {
                int c = 2 * x;
                rows[z * half + x] = W0 * in[row + c]
                        + W1 * (in[row + edge(c - 1, n, wrap)] + in[row + edge(c + 1, n, wrap)])
                        + W2 * (in[row + edge(c - 2, n, wrap)] + in[row + edge(c + 2, n, wrap)]);
            }
        });
        // 2. along z: half rows of half samples
        float[] out = new float[half * half];
        rows(half).forEach(z -> {
            int c = 2 * z;
            int r0 = c * half;
            int rm1 = edge(c - 1, n, wrap) * half;
            int rp1 = edge(c + 1, n, wrap) * half;
            int rm2 = edge(c - 2, n, wrap) * half;
            int rp2 = edge(c + 2, n, wrap) * half;
            for (int x = 0; x < half; x++) {
                out[z * half + x] = W0 * rows[r0 + x] + W1 * (rows[rm1 + x] + rows[rp1 + x])
                        + W2 * (rows[rm2 + x] + rows[rp2 + x]);
            }
        });
        return new HeightMap(half, fine.spacing() * 2, out, wrap);
    }

    /** Index i of a line of n samples: wrapped for periodic maps, clamped to the edge for imported ones. */
    private static int edge(int i, int n, boolean wrap) {
        return wrap ? i & (n - 1) : Math.max(0, Math.min(n - 1, i));
    }

    private static IntStream rows(int n) {
        IntStream rows = IntStream.range(0, n);
        return n >= PARALLEL_MIN_SIZE ? rows.parallel() : rows;
    }

    public HeightMap level(int k) {
        return levels.get(k);
    }

    public int levelCount() {
        return levels.size();
    }

    public HeightMap base() {
        return levels.get(0);
    }

    @Override
    public int levels() {
        return levels.size();
    }

    @Override
    public double spacing(int level) {
        return levels.get(level).spacing();
    }

    @Override
    public double height(int level, double x, double z) {
        return levels.get(level).heightAt(x, z);
    }

    @Override
    public double lowest() {
        return base().min();
    }

    @Override
    public double highest() {
        return base().max();
    }

    /** The level's own samples, wrapped (periodic) or clamped (imported) outside the tile. */
    @Override
    public float[] level(int level, long ix0, long iz0, int n) {
        HeightMap map = levels.get(level);
        int half = map.size() / 2;
        float[] h = new float[n * n];
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                h[j * n + i] = map.sample((int) (ix0 + i + half), (int) (iz0 + j + half));
            }
        }
        return h;
    }
}

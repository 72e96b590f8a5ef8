package org.openworld.engine.terrain;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;
import org.jtransforms.fft.DoubleFFT_2D;
import org.openworld.engine.core.FftThreads;

/**
 * Image quilting (Efros and Freeman 2001, "Image Quilting for Texture Synthesis and Transfer"; the paper's proposed
 * cure for its repeating detail textures, section 6): a texture {@link #FACTOR} times the exemplar's side, made of
 * square blocks copied from the exemplar, each overlapping its placed neighbours by {@link #OVERLAP} texels and
 * chosen so that it agrees with them there; the seam between old and new then runs where they differ least. Both
 * textures of a material (albedo, and the detail map with its normal, relief and gloss) are cut together, so one
 * seam serves every map and the bumps stay under their colours.
 *
 * <p><b>Blocks.</b> {@link #STEP} texels apart, {@code STEP + OVERLAP} wide, in rows from the top left. For each, the
 * overlap error of a candidate source offset u is the sum of squared differences, over the block's overlap with
 * what is already placed (mask M, contents T), between the exemplar X at u and the quilt:
 * <pre>
 *   E(u) = Σ_p M(p) Σ_c (X_c(p + u) − T_c(p))²
 *        = (M ⋆ Σ_c X_c²)(u) − 2 Σ_c (M T_c ⋆ X_c)(u) + Σ_p M Σ_c T_c²
 * </pre>
 * Each ⋆ (a cross-correlation) is a product of spectra (correlation theorem), so all offsets cost a few FFTs. The
 * exemplar is periodic, so every offset is a whole block. The match uses the albedo's three channels and the relief,
 * averaged over {@link #MATCH}² texels (offsets every {@code MATCH} texels: 64² candidates on a 512² exemplar).
 * Among the offsets within {@link #TOLERANCE} of the smallest error one is drawn at random (the paper's rule: the
 * best match alone would repeat itself), leaving out any whose source overlaps that of a placed neighbour above,
 * below, left or right: the exemplar's own continuation matches a neighbour perfectly and would rebuild the tile.
 *
 * <p><b>The cut.</b> In each overlap strip the error per texel e = Σ_c (new − old)², over all seven channels (albedo
 * rgb, normal xy, relief, gloss), and the minimum-error boundary through the strip along its length, moving at most
 * one texel sideways per step, by dynamic programming: E_i(w) = e_i(w) + min(E_{i−1}(w−1), E_{i−1}(w),
 * E_{i−1}(w+1)), then back from the smallest end. Old texels keep their side of the cut, the new block fills the
 * other; where two strips cross (a block with neighbours left and above), a texel is new only on the new side of
 * both cuts.
 *
 * <p><b>Periodic.</b> The renderer tiles the quilt, so it wraps: the last column of blocks overlaps the first (its
 * right strip) and the last row the first row (its bottom strip), cut the same way; the quilt's last column then
 * continues into its first like any interior pair, and the whole repeats only every FACTOR exemplar sides.
 *
 * <p><b>Cost.</b> Per block four 64² FFTs (three forward, of the mask and the masked features two to a transform;
 * one inverse) and a pass over the candidates: 256 blocks per material at the defaults, the three materials in
 * parallel; the terrain reports the time as its {@code quilting} stage (a few seconds on two busy cores).
 * Deterministic: one seeded random stream per material, FFTs pinned ({@link FftThreads}).
 *
 * <p><b>Limits.</b> The quilt still repeats, FACTOR times further apart; memory grows with FACTOR² (a 2048² array
 * of three layers, two textures and their mips is 128 MiB). Features larger than a block (the rock's strata, the
 * grass's clumps) are cut short at seams; a seam that finds no agreeing path shows as a faint edge.
 */
final class ImageQuilting {

    /** Quilt side / exemplar side: the quilt repeats every 4 exemplar sides (10.8 m at the default 2.7 m tile). */
    static final int FACTOR = 4;
    /** Texels from one block to the next: a quarter of the 512 exemplar, 68 cm, more than a rock slab. */
    static final int STEP = 128;
    /** Texels two neighbouring blocks share, where the seam is cut: a fifth of the block (the paper takes a sixth). */
    static final int OVERLAP = 32;
    /** Block side. */
    static final int BLOCK = STEP + OVERLAP;
    /** Texels averaged per side for the match, and the spacing of the candidate offsets. */
    static final int MATCH = 8;
    /** Candidates whose error is within this fraction of the best are drawn from (the paper's 0.1). */
    static final double TOLERANCE = 0.1;
    /** Channels matched: albedo r, g, b and the relief. */
    private static final int FEATURES = 4;

    /** One seam: its cost along the cut, and along the cheapest straight line through the same strip. */
    record Seam(double cut, double straight) {
    }

    /**
     * A quilted material: RGBA8 albedo and detail, {@code size}² texels, the source offset (in exemplar texels) of
     * each block, row by row ({@code blocks}² of them), and every seam cut.
     */
    record Quilt(int size, byte[] albedo, byte[] detail, int blocks, int[] sourceX, int[] sourceY,
                 List<Seam> seams) {
    }

    private final int n;
    private final int size;
    private final int blocks;
    private final byte[] albedoIn;
    private final byte[] detailIn;
    private final byte[] albedo;
    private final byte[] detail;
    private final int coarse;       // candidate grid side: n / MATCH
    private final int coarseSize;   // the quilt's matching grid side: size / MATCH
    private final float[][] quiltFeatures;
    private final double[][] exemplarSpectra; // FEATURES spectra of X_c, then that of Σ_c X_c²
    private final DoubleFFT_2D fft;
    private final int[] sourceX;
    private final int[] sourceY;
    private final List<Seam> seams = new ArrayList<>();

    /** A quilter of this exemplar ({@link #quilt} runs one); nothing is placed yet. */
    ImageQuilting(byte[] albedo, byte[] detail, int n) {
        if (n % STEP != 0 || n < 2 * BLOCK) {
            throw new IllegalArgumentException("exemplar side " + n + " must be a multiple of " + STEP
                    + " and at least " + 2 * BLOCK);
        }
        this.n = n;
        this.size = FACTOR * n;
        this.blocks = size / STEP;
        this.albedoIn = albedo;
        this.detailIn = detail;
        this.albedo = new byte[size * size * 4];
        this.detail = new byte[size * size * 4];
        this.coarse = n / MATCH;
        this.coarseSize = size / MATCH;
        this.quiltFeatures = new float[FEATURES][coarseSize * coarseSize];
        this.fft = new DoubleFFT_2D(coarse, coarse);
        this.sourceX = new int[blocks * blocks];
        this.sourceY = new int[blocks * blocks];
        float[][] x = new float[FEATURES][coarse * coarse];
        for (int cy = 0; cy < coarse; cy++) {
            for (int cx = 0; cx < coarse; cx++) {
                average(albedo, detail, n, cx * MATCH, cy * MATCH, x, cy * coarse + cx);
            }
        }
        exemplarSpectra = new double[FEATURES + 1][];
        double[] squares = new double[2 * coarse * coarse];
        for (int c = 0; c < FEATURES; c++) {
            double[] a = new double[2 * coarse * coarse];
            for (int i = 0; i < coarse * coarse; i++) {
                a[i] = x[c][i];
                squares[i] += (double) x[c][i] * x[c][i];
            }
            exemplarSpectra[c] = a;
        }
        exemplarSpectra[FEATURES] = squares;
        FftThreads.pinned(() -> {
            for (double[] a : exemplarSpectra) {
                fft.realForwardFull(a);
            }
        });
    }

    /**
     * Quilts one material's exemplar, {@code n}² RGBA8 albedo and detail texels (periodic, {@code n} a multiple of
     * {@link #STEP}), into a periodic texture {@link #FACTOR} times as wide, choosing among near-best blocks with
     * {@code rng}: the same exemplar and stream give the same bytes.
     */
    static Quilt quilt(byte[] albedo, byte[] detail, int n, SplittableRandom rng) {
        ImageQuilting q = new ImageQuilting(albedo, detail, n);
        q.placeAll(rng);
        return q.result();
    }

    /** Places every block, in rows from the top left. */
    void placeAll(SplittableRandom rng) {
        for (int j = 0; j < blocks; j++) {
            for (int i = 0; i < blocks; i++) {
                place(i, j, rng);
            }
        }
    }

    /** The quilt as placed so far. */
    Quilt result() {
        return new Quilt(size, albedo, detail, blocks, sourceX, sourceY, List.copyOf(seams));
    }

    /** Chooses and places block (i, j), cutting its seams with what is already placed. */
    private void place(int i, int j, SplittableRandom rng) {
        boolean left = i > 0;
        boolean top = j > 0;
        boolean right = i == blocks - 1;  // wraps onto the first column
        boolean bottom = j == blocks - 1; // wraps onto the first row
        int best = choose(i, j, left, top, right, bottom, rng);
        int u = (best % coarse) * MATCH;
        int v = (best / coarse) * MATCH;
        sourceX[j * blocks + i] = u;
        sourceY[j * blocks + i] = v;
        int x0 = i * STEP;
        int y0 = j * STEP;
        int[] cutLeft = left ? cut(x0, y0, u, v, true, 0) : null;
        int[] cutRight = right ? cut(x0, y0, u, v, true, STEP) : null;
        int[] cutTop = top ? cut(x0, y0, u, v, false, 0) : null;
        int[] cutBottom = bottom ? cut(x0, y0, u, v, false, STEP) : null;
        for (int by = 0; by < BLOCK; by++) {
            for (int bx = 0; bx < BLOCK; bx++) {
                // old texels keep their side of every cut: left and above the old side of the left and top strips,
                // right and below that of the wrapped right and bottom strips
                boolean fresh = (cutLeft == null || bx >= OVERLAP || bx >= cutLeft[by])
                        && (cutRight == null || bx < STEP || bx - STEP < cutRight[by])
                        && (cutTop == null || by >= OVERLAP || by >= cutTop[bx])
                        && (cutBottom == null || by < STEP || by - STEP < cutBottom[bx]);
                if (fresh) {
                    int to = 4 * (wrap(y0 + by, size) * size + wrap(x0 + bx, size));
                    int from = 4 * (wrap(v + by, n) * n + wrap(u + bx, n));
                    System.arraycopy(albedoIn, from, albedo, to, 4);
                    System.arraycopy(detailIn, from, detail, to, 4);
                }
            }
        }
        int c0x = x0 / MATCH;
        int c0y = y0 / MATCH;
        for (int cy = 0; cy < BLOCK / MATCH; cy++) {
            for (int cx = 0; cx < BLOCK / MATCH; cx++) {
                int qx = wrap(c0x + cx, coarseSize);
                int qy = wrap(c0y + cy, coarseSize);
                average(albedo, detail, size, qx * MATCH, qy * MATCH, quiltFeatures, qy * coarseSize + qx);
            }
        }
    }

    /**
     * The candidate (index cy · coarse + cx on the matching grid) drawn for block (i, j): any, for the first block;
     * else one within the tolerance of the least overlap error among those whose source does not overlap a placed
     * neighbour's.
     */
    private int choose(int i, int j, boolean left, boolean top, boolean right, boolean bottom,
                       SplittableRandom rng) {
        if (!left && !top) {
            return rng.nextInt(coarse * coarse);
        }
        double[] error = overlapError(i, j, left, top, right, bottom);
        List<Integer> neighbours = new ArrayList<>();
        if (left) {
            neighbours.add(j * blocks + i - 1);
        }
        if (top) {
            neighbours.add((j - 1) * blocks + i);
        }
        if (right) {
            neighbours.add(j * blocks);
        }
        if (bottom) {
            neighbours.add(i);
        }
        boolean[] allowed = new boolean[coarse * coarse];
        double least = Double.POSITIVE_INFINITY;
        for (int c = 0; c < allowed.length; c++) {
            int u = (c % coarse) * MATCH;
            int v = (c / coarse) * MATCH;
            boolean apart = true;
            for (int k : neighbours) {
                apart &= Math.abs(centred(u - sourceX[k])) >= BLOCK || Math.abs(centred(v - sourceY[k])) >= BLOCK;
            }
            allowed[c] = apart;
            if (apart) {
                least = Math.min(least, error[c]);
            }
        }
        if (least == Double.POSITIVE_INFINITY) {
            // the neighbours' sources cover the exemplar between them (possible only for a block of the last row or
            // column, which has three or four placed neighbours): choose among all
            Arrays.fill(allowed, true);
            for (double e : error) {
                least = Math.min(least, e);
            }
        }
        double limit = least * (1 + TOLERANCE) + 1e-9;
        int[] near = new int[allowed.length];
        int count = 0;
        for (int c = 0; c < allowed.length; c++) {
            if (allowed[c] && error[c] <= limit) {
                near[count++] = c;
            }
        }
        return near[rng.nextInt(count)];
    }

    /**
     * E(u) for every candidate offset u (the class comment's formula; index (v / MATCH) · (n / MATCH) + u / MATCH) of
     * block (i, j) over the strips named, against the quilt as it is now, by FFT on the matching grid.
     */
    double[] overlapError(int i, int j, boolean left, boolean top, boolean right, boolean bottom) {
        int side = BLOCK / MATCH;
        int overlap = OVERLAP / MATCH;
        int step = STEP / MATCH;
        int cc = coarse * coarse;
        // the mask and the masked features, real, two to a complex transform (real and imaginary parts)
        double[][] packed = new double[(FEATURES + 2) / 2][2 * cc];
        double constant = 0;
        for (int cy = 0; cy < side; cy++) {
            for (int cx = 0; cx < side; cx++) {
                boolean old = (left && cx < overlap) || (right && cx >= step)
                        || (top && cy < overlap) || (bottom && cy >= step);
                if (!old) {
                    continue;
                }
                int q = wrap(j * step + cy, coarseSize) * coarseSize + wrap(i * step + cx, coarseSize);
                int p = 2 * (cy * coarse + cx);
                packed[0][p] = 1;
                for (int c = 0; c < FEATURES; c++) {
                    double t = quiltFeatures[c][q];
                    packed[(c + 1) / 2][p + (c + 1) % 2] = t;
                    constant += t * t;
                }
            }
        }
        double[] sum = new double[2 * cc];
        FftThreads.pinned(() -> {
            for (double[] a : packed) {
                fft.complexForward(a);
            }
            // conj(A) B for each correlation, summed: the squares' term minus twice the cross terms; the spectra of
            // the real parts a and imaginary parts b of a packed transform Z are (Z(k) + conj Z(-k)) / 2 and
            // (Z(k) - conj Z(-k)) / 2i
            double[] squares = exemplarSpectra[FEATURES];
            for (int ky = 0; ky < coarse; ky++) {
                for (int kx = 0; kx < coarse; kx++) {
                    int re = 2 * (ky * coarse + kx);
                    int im = re + 1;
                    int nre = 2 * (((coarse - ky) % coarse) * coarse + (coarse - kx) % coarse);
                    int nim = nre + 1;
                    double sr = 0;
                    double si = 0;
                    for (int r = 0; r <= FEATURES; r++) {
                        double[] z = packed[r / 2];
                        double ar;
                        double ai;
                        if (r % 2 == 0) {
                            ar = (z[re] + z[nre]) / 2;
                            ai = (z[im] - z[nim]) / 2;
                        } else {
                            ar = (z[im] + z[nim]) / 2;
                            ai = (z[nre] - z[re]) / 2;
                        }
                        double[] x = r == 0 ? squares : exemplarSpectra[r - 1];
                        double weight = r == 0 ? 1 : -2;
                        sr += weight * (ar * x[re] + ai * x[im]);
                        si += weight * (ar * x[im] - ai * x[re]);
                    }
                    sum[re] = sr;
                    sum[im] = si;
                }
            }
            fft.complexInverse(sum, true);
        });
        double[] error = new double[cc];
        for (int k = 0; k < cc; k++) {
            error[k] = Math.max(0, sum[2 * k] + constant);
        }
        return error;
    }

    /**
     * The minimum-error cut through one overlap strip of the block at (x0, y0) taking source (u, v): a vertical
     * strip ({@code vertical}) at block columns {@code offset} .. offset + OVERLAP − 1, or a horizontal one at those
     * rows. Returns, along the strip, the first texel (across it) of the cut; records the seam.
     */
    private int[] cut(int x0, int y0, int u, int v, boolean vertical, int offset) {
        double[] e = new double[BLOCK * OVERLAP];
        for (int l = 0; l < BLOCK; l++) {
            for (int w = 0; w < OVERLAP; w++) {
                int bx = vertical ? offset + w : l;
                int by = vertical ? l : offset + w;
                int to = 4 * (wrap(y0 + by, size) * size + wrap(x0 + bx, size));
                int from = 4 * (wrap(v + by, n) * n + wrap(u + bx, n));
                double sum = 0;
                for (int c = 0; c < 4; c++) {
                    if (c < 3) {
                        double d = ((albedo[to + c] & 0xFF) - (albedoIn[from + c] & 0xFF)) / 255.0;
                        sum += d * d;
                    }
                    double d = ((detail[to + c] & 0xFF) - (detailIn[from + c] & 0xFF)) / 255.0;
                    sum += d * d;
                }
                e[l * OVERLAP + w] = sum;
            }
        }
        int[] path = minimumPath(e, BLOCK, OVERLAP);
        double cost = 0;
        for (int l = 0; l < BLOCK; l++) {
            cost += e[l * OVERLAP + path[l]];
        }
        double straight = Double.POSITIVE_INFINITY;
        for (int w = 0; w < OVERLAP; w++) {
            double line = 0;
            for (int l = 0; l < BLOCK; l++) {
                line += e[l * OVERLAP + w];
            }
            straight = Math.min(straight, line);
        }
        seams.add(new Seam(cost, straight));
        return path;
    }

    /**
     * The path of least summed error through {@code e} ({@code length} rows of {@code width}), one texel per row,
     * moving at most one texel sideways from a row to the next: its texel in each row.
     */
    static int[] minimumPath(double[] e, int length, int width) {
        double[] total = new double[length * width];
        System.arraycopy(e, 0, total, 0, width);
        for (int l = 1; l < length; l++) {
            for (int w = 0; w < width; w++) {
                double best = total[(l - 1) * width + w];
                if (w > 0) {
                    best = Math.min(best, total[(l - 1) * width + w - 1]);
                }
                if (w < width - 1) {
                    best = Math.min(best, total[(l - 1) * width + w + 1]);
                }
                total[l * width + w] = e[l * width + w] + best;
            }
        }
        int[] path = new int[length];
        int end = 0;
        for (int w = 1; w < width; w++) {
            if (total[(length - 1) * width + w] < total[(length - 1) * width + end]) {
                end = w;
            }
        }
        path[length - 1] = end;
        for (int l = length - 2; l >= 0; l--) {
            int next = path[l + 1];
            int best = next;
            for (int w = Math.max(0, next - 1); w <= Math.min(width - 1, next + 1); w++) {
                if (total[l * width + w] < total[l * width + best]) {
                    best = w;
                }
            }
            path[l] = best;
        }
        return path;
    }

    /**
     * The matched features (albedo r, g, b and relief, 0..1) of the MATCH² texels at (x, y) of a {@code side}²
     * texture, averaged, into {@code out[c][index]}.
     */
    private static void average(byte[] albedo, byte[] detail, int side, int x, int y, float[][] out, int index) {
        float r = 0;
        float g = 0;
        float b = 0;
        float h = 0;
        for (int dy = 0; dy < MATCH; dy++) {
            for (int dx = 0; dx < MATCH; dx++) {
                int t = 4 * ((y + dy) * side + x + dx);
                r += albedo[t] & 0xFF;
                g += albedo[t + 1] & 0xFF;
                b += albedo[t + 2] & 0xFF;
                h += detail[t + 2] & 0xFF;
            }
        }
        float scale = 1f / (255 * MATCH * MATCH);
        out[0][index] = r * scale;
        out[1][index] = g * scale;
        out[2][index] = b * scale;
        out[3][index] = h * scale;
    }

    /** An exemplar offset difference brought into −n/2 .. n/2 (the exemplar is periodic). */
    private int centred(int d) {
        return Math.floorMod(d + n / 2, n) - n / 2;
    }

    private static int wrap(int i, int side) {
        return Math.floorMod(i, side);
    }
}

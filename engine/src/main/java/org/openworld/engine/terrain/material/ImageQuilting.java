package org.openworld.engine.terrain.material;

/**
 * The minimum-error boundary cut of image quilting (Efros and Freeman 2001, "Image Quilting for Texture Synthesis and
 * Transfer"; the paper's proposed cure for its repeating detail textures, section 6), which {@link WangTiles} cuts
 * its tiles with. Where two pieces of texture overlap, the seam between them should run where they differ least, not
 * along a straight line: with e the error per texel of the overlap (for the terrain e = Σ_c (a − b)² over albedo rgb,
 * normal xy, relief and gloss, so one seam serves every map and the bumps stay under their colours), the path along
 * the overlap, one texel per row and moving at most one texel sideways from a row to the next, of least summed e, by
 * dynamic programming:
 * <pre>
 *   E_i(w) = e_i(w) + min(E_{i−1}(w−1), E_{i−1}(w), E_{i−1}(w+1))
 * </pre>
 * then back from the smallest end. Texels on one side of the path keep the old piece, the other side takes the new.
 *
 * <p><b>Cost.</b> Three comparisons per texel of the overlap, and one pass back along it.
 *
 * <p><b>Limits.</b> A path, not a region: features larger than the overlap are cut short at the seam, and where the
 * pieces agree nowhere the cheapest path is still a visible edge.
 */
final class ImageQuilting {

    /** Texels two pieces share where a seam is cut between them: a fifth of a 160-texel block (the paper: a sixth). */
    static final int OVERLAP = 32;

    /** One seam: its cost along the cut, and along the straight line the cut replaces. */
    record Seam(double cut, double straight) {
    }

    private ImageQuilting() {
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

    /** The summed error along a path through {@code e} ({@code width} per row). */
    static double cost(double[] e, int width, int[] path) {
        double sum = 0;
        for (int l = 0; l < path.length; l++) {
            sum += e[l * width + path[l]];
        }
        return sum;
    }
}

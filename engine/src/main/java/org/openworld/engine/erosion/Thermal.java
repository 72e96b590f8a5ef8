package org.openworld.engine.erosion;

/**
 * Thermal erosion (Musgrave, Kolb and Mace 1989): wherever the drop to a side neighbour exceeds the talus slope,
 * material slides down, an eighth of the excess per pass (so a cell losing to all four sides at once keeps half
 * its excess, and no pass overshoots into a pit). Each pass takes what moves from the heights of the pass before
 * (Jacobi), so the result does not depend on the order cells are visited, and every amount leaves one cell and
 * reaches another: the volume is kept up to float rounding.
 */
final class Thermal {

    /** Passes: a slope this many cells long above the talus is brought to it. */
    static final int PASSES = 24;
    /** Share of the excess drop that moves in one pass, per side. */
    private static final float SHARE = 0.125f;
    private static final int[] DX = {1, -1, 0, 0};
    private static final int[] DZ = {0, 0, 1, -1};

    private Thermal() {
    }

    /**
     * Relaxes {@code h} in place towards slopes no steeper than {@code talus}.
     *
     * @param h        {@code n × n} heights, row-major
     * @param spacing  metres between samples
     * @param talus    the angle of repose as a gradient, m/m
     * @param periodic whether neighbours wrap across the edges (otherwise nothing crosses them)
     */
    static void relax(float[] h, int n, double spacing, double talus, boolean periodic) {
        float limit = (float) (talus * spacing);
        float[] moved = new float[h.length];
        for (int pass = 0; pass < PASSES; pass++) {
            java.util.Arrays.fill(moved, 0);
            for (int z = 0; z < n; z++) {
                for (int x = 0; x < n; x++) {
                    int i = z * n + x;
                    for (int k = 0; k < DX.length; k++) {
                        int nx = x + DX[k];
                        int nz = z + DZ[k];
                        if (!periodic && (nx < 0 || nz < 0 || nx >= n || nz >= n)) {
                            continue;
                        }
                        int j = Math.floorMod(nz, n) * n + Math.floorMod(nx, n);
                        float excess = h[i] - h[j] - limit;
                        if (excess > 0) {
                            float q = SHARE * excess;
                            moved[i] -= q;
                            moved[j] += q;
                        }
                    }
                }
            }
            for (int i = 0; i < h.length; i++) {
                h[i] += moved[i];
            }
        }
    }
}

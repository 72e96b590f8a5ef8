package org.openworld.engine.grass;

import org.openworld.engine.core.HeightField;
import org.openworld.engine.environment.SnowLine;
import org.openworld.engine.vegetation.PlacementField;

/**
 * Where grass grows around the viewer and how thick, sampled every {@link #SPACING} metres on a square of the world's
 * grid: per sample the ground's height and the grass's share, 0 to 1. The GPU reads it as a texture
 * ({@link GrassDraw}); no blade has data of its own on the CPU.
 *
 * <p>The share is 0 where no grass grows: under {@link Rules#lowest} (the water and its wet rim), at or over the
 * {@link SnowLine}'s full line and where the ground is steeper than {@link Rules#maxGradient} (rock). Elsewhere it is
 * the vegetation's {@link PlacementField#ground}, the land's moisture (not its tree line), where the world has that
 * field (1 where it has none), times the chance of no snow ({@code 1 − SnowLine.chanceAt(h)}): between the snow line's start
 * and its full line the ground's snow lies in patches, and the grass thins as they close up. The samples lie on world
 * multiples of the spacing, and each depends only on its place and the land: a sample is the same in every square the
 * viewer's moves make ({@code GrassFieldTest}).
 *
 * <p>Cost: {@code (n + 2)²} height lookups and {@code n²} of the placement field (five height lookups each) for a
 * square of {@code n} samples a side; 110 samples for the default 40 m, some 75 000 lookups, a few milliseconds.
 */
final class GrassField {

    /** Blades in one tuft, the instance the GPU draws in each cell of the world's grid. */
    static final int BLADES = 4;
    /** The share of the distance over which blades thin away (the last 30 %). */
    static final double FADE_SHARE = 0.3;
    /** Metres between samples: the terrain's finest height samples are 2 m apart, so 1 m follows its bends. */
    static final double SPACING = 1;
    /** The share of the distance the viewer may move before the square is made again around it. */
    static final double REBUILD_SHARE = 0.25;

    /**
     * The rules: grass grows from {@code lowest} metres up, thinning under the {@code snow} (null: a world without
     * snow) and gone at its full line, on ground no steeper than {@code maxGradient} (rise over run).
     */
    record Rules(double lowest, SnowLine snow, double maxGradient) {
    }

    private final long firstX;
    private final long firstZ;
    private final int size;
    private final float[] heights;
    private final float[] shares;

    private GrassField(long firstX, long firstZ, int size, float[] heights, float[] shares) {
        this.firstX = firstX;
        this.firstZ = firstZ;
        this.size = size;
        this.heights = heights;
        this.shares = shares;
    }

    /**
     * The square reaching {@code (1 + REBUILD_SHARE) · distance} from (x, z) on every side.
     *
     * @param placement the vegetation's field, or null for a share of 1 wherever the rules allow grass
     */
    static GrassField around(double x, double z, double distance, HeightField land, PlacementField placement,
                             Rules rules) {
        double reach = (1 + REBUILD_SHARE) * distance;
        long fx = (long) Math.floor((x - reach) / SPACING);
        long fz = (long) Math.floor((z - reach) / SPACING);
        int n = (int) Math.ceil(2 * reach / SPACING) + 2;
        // 1. heights with a rim of one sample, for the slopes at the edges
        int m = n + 2;
        double[] rim = new double[m * m];
        for (int j = 0; j < m; j++) {
            for (int i = 0; i < m; i++) {
                rim[j * m + i] = land.heightAt((fx + i - 1) * SPACING, (fz + j - 1) * SPACING);
            }
        }
        // 2. the rules, then the land's share
        float[] heights = new float[n * n];
        float[] shares = new float[n * n];
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                int r = (j + 1) * m + i + 1;
                double h = rim[r];
                double gx = (rim[r + 1] - rim[r - 1]) / (2 * SPACING);
                double gz = (rim[r + m] - rim[r - m]) / (2 * SPACING);
                double snowless = rules.snow() == null ? 1 : 1 - rules.snow().chanceAt(h);
                boolean grows = h >= rules.lowest() && snowless > 0 && Math.hypot(gx, gz) <= rules.maxGradient();
                double wx = (fx + i) * SPACING;
                double wz = (fz + j) * SPACING;
                heights[j * n + i] = (float) h;
                shares[j * n + i] = !grows ? 0
                        : (float) (snowless * (placement == null ? 1 : placement.ground(wx, wz, h)));
            }
        }
        return new GrassField(fx, fz, n, heights, shares);
    }

    /** The first sample's index on the world's grid, east (x) and south (z): it lies at index × spacing. */
    long firstX() {
        return firstX;
    }

    long firstZ() {
        return firstZ;
    }

    /** Samples a side. */
    int size() {
        return size;
    }

    /** The world's x and z of the square's middle, metres: where the viewer was when it was made, nearly. */
    double middleX() {
        return (firstX + (size - 1) / 2.0) * SPACING;
    }

    double middleZ() {
        return (firstZ + (size - 1) / 2.0) * SPACING;
    }

    /** The height and share of sample (i, j) of the square. */
    float height(int i, int j) {
        return heights[j * size + i];
    }

    float share(int i, int j) {
        return shares[j * size + i];
    }

    /**
     * The lowest and highest ground over the world's x in [x0, x1] and z in [z0, z1], metres: the samples around it
     * of the square in it (a box for the frustum); null where no grass grows there (or it is all outside the square,
     * where the shader draws none).
     */
    float[] range(double x0, double z0, double x1, double z1) {
        int i0 = (int) Math.max(0, Math.floor(x0 / SPACING) - firstX);
        int j0 = (int) Math.max(0, Math.floor(z0 / SPACING) - firstZ);
        int i1 = (int) Math.min(size - 1, Math.ceil(x1 / SPACING) - firstX);
        int j1 = (int) Math.min(size - 1, Math.ceil(z1 / SPACING) - firstZ);
        float low = Float.POSITIVE_INFINITY;
        float high = Float.NEGATIVE_INFINITY;
        boolean grows = false;
        for (int j = j0; j <= j1; j++) {
            for (int i = i0; i <= i1; i++) {
                low = Math.min(low, height(i, j));
                high = Math.max(high, height(i, j));
                grows |= share(i, j) > 0;
            }
        }
        return grows ? new float[] {low, high} : null;
    }

    /** The samples as the texture holds them: per sample height (m), share, 0, 0. */
    float[] texels() {
        float[] t = new float[4 * size * size];
        for (int k = 0; k < size * size; k++) {
            t[4 * k] = heights[k];
            t[4 * k + 1] = shares[k];
        }
        return t;
    }
}

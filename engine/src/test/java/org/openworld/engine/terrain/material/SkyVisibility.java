package org.openworld.engine.terrain.material;

import java.util.Arrays;
import java.util.stream.IntStream;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.HeightPyramid;

/**
 * The CPU reference of the sky's visibility ({@link HorizonSearch}, made on the GPU by {@link TileSky} and the
 * streamed world's blocks): the same search, in doubles, one sample at a time. The tests compare the GPU's maps with
 * it and read it where they need V at a place. On two cores about half a second for 512².
 */
public final class SkyVisibility {


    private final int size;
    private final double spacing;
    private final byte[] values;
    private final boolean periodic;

    private SkyVisibility(int size, double spacing, byte[] values, boolean periodic) {
        this.size = size;
        this.spacing = spacing;
        this.values = values;
        this.periodic = periodic;
    }

    /** The visibility on the first level of the pyramid no larger than {@link TileSky#MAX_SIZE}, as the tile's. */
    public static SkyVisibility of(HeightPyramid pyramid) {
        int level = 0;
        while (pyramid.level(level).size() > TileSky.MAX_SIZE) {
            level++;
        }
        return of(pyramid, level);
    }

    /** The visibility at the samples of pyramid level {@code level}, with the horizon searched over the pyramid. */
    static SkyVisibility of(HeightPyramid pyramid, int level) {
        HeightMap grid = pyramid.level(level);
        int n = grid.size();
        byte[] values = new byte[n * n];
        double[] cos = new double[HorizonSearch.DIRECTIONS];
        double[] sin = new double[HorizonSearch.DIRECTIONS];
        for (int m = 0; m < HorizonSearch.DIRECTIONS; m++) {
            cos[m] = Math.cos(2 * Math.PI * m / HorizonSearch.DIRECTIONS);
            sin[m] = Math.sin(2 * Math.PI * m / HorizonSearch.DIRECTIONS);
        }
        double d = grid.spacing();
        double[] distances = HorizonSearch.distances(d);
        int steps = distances.length;
        // per distance: the level read, where this grid's samples fall on it (g = col · scale + shift, in its
        // samples), and the step along each azimuth in its samples; all fixed, so the loop below only adds
        HeightMap[] levelAt = new HeightMap[steps];
        double[] scale = new double[steps];
        double[] shift = new double[steps];
        double[] inverse = new double[steps];
        double[][] stepX = new double[steps][HorizonSearch.DIRECTIONS];
        double[][] stepZ = new double[steps][HorizonSearch.DIRECTIONS];
        for (int j = 0; j < steps; j++) {
            double r = distances[j];
            HeightMap map = pyramid.level(HorizonSearch.levelAt(r, level, pyramid.levelCount(), pyramid::spacing));
            levelAt[j] = map;
            scale[j] = d / map.spacing();
            shift[j] = map.size() / 2.0 - n / 2.0 * scale[j];
            inverse[j] = 1 / r;
            for (int m = 0; m < HorizonSearch.DIRECTIONS; m++) {
                stepX[j][m] = r * cos[m] / map.spacing();
                stepZ[j][m] = r * sin[m] / map.spacing();
            }
        }
        IntStream.range(0, n).parallel().forEach(row -> {
            double[] horizon = new double[HorizonSearch.DIRECTIONS];
            for (int col = 0; col < n; col++) {
                float h0 = grid.sample(col, row);
                double gx = (grid.sample(col + 1, row) - grid.sample(col - 1, row)) / (2 * d);
                double gz = (grid.sample(col, row + 1) - grid.sample(col, row - 1)) / (2 * d);
                Arrays.fill(horizon, Double.NEGATIVE_INFINITY);
                for (int j = 0; j < steps; j++) {
                    double x = col * scale[j] + shift[j];
                    double z = row * scale[j] + shift[j];
                    for (int m = 0; m < HorizonSearch.DIRECTIONS; m++) {
                        double rise = (bilinear(levelAt[j], x + stepX[j][m], z + stepZ[j][m]) - h0) * inverse[j];
                        horizon[m] = Math.max(horizon[m], rise);
                    }
                }
                double sum = 0;
                for (int m = 0; m < HorizonSearch.DIRECTIONS; m++) {
                    sum += visibleShare(horizon[m], gx * cos[m] + gz * sin[m]);
                }
                values[row * n + col] = (byte) Math.round(255 * sum / HorizonSearch.DIRECTIONS);
            }
        });
        return new SkyVisibility(n, d, values, grid.periodic());
    }

    /** The visibility at world position (x, z), metres, 0..1 in steps of 1/255, at the nearest sample. */
    public double visibleAt(double x, double z) {
        return raw((int) Math.round(x / spacing + size / 2.0), (int) Math.round(z / spacing + size / 2.0)) / 255.0;
    }

    /** Samples per side. */
    int size() {
        return size;
    }

    /** The stored byte at (col, row), wrapped or clamped like the heights. */
    int raw(int col, int row) {
        int c = periodic ? col & (size - 1) : Math.max(0, Math.min(col, size - 1));
        int r = periodic ? row & (size - 1) : Math.max(0, Math.min(row, size - 1));
        return values[r * size + c] & 0xFF;
    }

    /**
     * cos² of the horizon's rise above the tangent plane along one azimuth, the two given as slopes (tangents): for
     * p = tan h and q = tan t, cos(h − t) = (1 + pq) / √((1 + p²)(1 + q²)), without a trigonometric call; 1 when
     * the horizon lies below the plane, 0 when it stands more than 90° above it (1 + pq < 0).
     */
    public static double visibleShare(double horizon, double plane) {
        if (horizon <= plane) {
            return 1;
        }
        double c = 1 + horizon * plane;
        return c <= 0 ? 0 : c * c / ((1 + horizon * horizon) * (1 + plane * plane));
    }

    /** The map's height at grid coordinates (gx, gz), in its samples, bilinearly; wrapped or clamped at its edges. */
    private static float bilinear(HeightMap map, double gx, double gz) {
        int n = map.size();
        float[] h = map.heights();
        int x0 = (int) Math.floor(gx);
        int z0 = (int) Math.floor(gz);
        float fx = (float) (gx - x0);
        float fz = (float) (gz - z0);
        int xa;
        int xb;
        int za;
        int zb;
        if (map.periodic()) {
            xa = x0 & (n - 1);
            xb = (x0 + 1) & (n - 1);
            za = (z0 & (n - 1)) * n;
            zb = ((z0 + 1) & (n - 1)) * n;
        } else {
            xa = Math.max(0, Math.min(n - 1, x0));
            xb = Math.max(0, Math.min(n - 1, x0 + 1));
            za = Math.max(0, Math.min(n - 1, z0)) * n;
            zb = Math.max(0, Math.min(n - 1, z0 + 1)) * n;
        }
        float top = h[za + xa] + (h[za + xb] - h[za + xa]) * fx;
        float bottom = h[zb + xa] + (h[zb + xb] - h[zb + xa]) * fx;
        return top + (bottom - top) * fz;
    }

}

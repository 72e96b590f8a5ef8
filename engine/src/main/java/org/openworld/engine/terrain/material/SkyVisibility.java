package org.openworld.engine.terrain.material;

import java.util.Arrays;
import java.util.function.IntToDoubleFunction;
import java.util.stream.IntStream;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.HeightPyramid;

/**
 * How much of its sky each place of the ground sees (the light in the shadows): horizon-based ambient
 * occlusion from the height field, one value per sample of a map as fine as the snow map, computed once on the CPU
 * when the world is built.
 *
 * <p>Along each of {@value #DIRECTIONS} azimuths φ the horizon is the highest elevation at which the ground is seen,
 * {@code tan h_φ = max_r (H(p + r·φ) − H(p)) / r}, over distances r growing by {@value #STEP_GROWTH} from one sample
 * to {@value #REACH_METRES} m, each read from the pyramid level whose samples lie about {@code r / 4} apart (a far
 * peak needs no fine level, and the low-passed level does not alias). The ground's own slope hides nothing that the
 * sky light does not already leave out for a tilted normal, so only what rises above the tangent plane counts: the
 * excess angle {@code α_φ = max(0, h_φ − t_φ)}, t_φ the plane's elevation along φ. In one azimuth the sky between
 * elevations α and 90° gives the share {@code ∫_α^{π/2} sin e cos e de / ∫_0^{π/2} sin e cos e de = cos² α} of a
 * horizontal surface's irradiance from that azimuth (the cosine of incidence times the solid angle's cos e), so
 * <pre>  V = (1/N) Σ_φ cos² α_φ</pre>
 * is 1 on open ground and on a plain slope, about 0.75 at the foot of a long vertical wall, and lower down a narrow
 * gorge. The material shades with {@code V · E_sky(n) + (1 − V) · E_hidden}: the hidden sky replaced by the light
 * of the terrain that hides it, {@code E_hidden = albedo · (E_sun · sin(elevation) / 2 + E_up)} (the sky system's
 * reckoning: terrain lit by the sky and, since half of what surrounds a place faces the sun, by half the sun).
 *
 * <p>Cost: {@code N · log(R/d) / log(growth)} bilinear lookups per sample, made on the first pyramid level of at
 * most {@value #MAX_SIZE}² samples (8 m apart on the default map: occlusion varies over tens of metres) and
 * resampled to the snow map's grid, whose texture carries it: about half a second on two cores for 512². Limits:
 * eight azimuths miss a narrow notch between them; the tangent plane stands in for the hemisphere of a tilted surface
 * (exact for a horizontal one); the sky is taken as uniform, so a wall hiding the sun's bright
 * side of the sky darkens as much as one hiding the dim side; the occluder's light is the same everywhere, so the
 * shadowed face of the wall that casts a shadow counts as half sunlit.
 */
public final class SkyVisibility {

    /** Azimuths at which the horizon is found. */
    public static final int DIRECTIONS = 8;
    /** How far the horizon is searched, metres: beyond, a 1 km mountain stands under 20° and hides little. */
    static final double REACH_METRES = 3000;
    /** Ratio of consecutive search distances. */
    static final double STEP_GROWTH = 1.4;
    /** Largest side of the map, samples. */
    public static final int MAX_SIZE = 512;
    /** Samples of the level read at distance r are at most r / LEVEL_SPAN apart. */
    private static final double LEVEL_SPAN = 4;

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

    /** The visibility on the first level of the pyramid no larger than {@link #MAX_SIZE}. */
    public static SkyVisibility of(HeightPyramid pyramid) {
        int level = 0;
        while (pyramid.level(level).size() > MAX_SIZE) {
            level++;
        }
        return of(pyramid, level);
    }

    /** The visibility at the samples of pyramid level {@code level}, with the horizon searched over the pyramid. */
    static SkyVisibility of(HeightPyramid pyramid, int level) {
        HeightMap grid = pyramid.level(level);
        int n = grid.size();
        byte[] values = new byte[n * n];
        double[] cos = new double[DIRECTIONS];
        double[] sin = new double[DIRECTIONS];
        for (int m = 0; m < DIRECTIONS; m++) {
            cos[m] = Math.cos(2 * Math.PI * m / DIRECTIONS);
            sin[m] = Math.sin(2 * Math.PI * m / DIRECTIONS);
        }
        double d = grid.spacing();
        double[] distances = distances(d);
        int steps = distances.length;
        // per distance: the level read, where this grid's samples fall on it (g = col · scale + shift, in its
        // samples), and the step along each azimuth in its samples; all fixed, so the loop below only adds
        HeightMap[] levelAt = new HeightMap[steps];
        double[] scale = new double[steps];
        double[] shift = new double[steps];
        double[] inverse = new double[steps];
        double[][] stepX = new double[steps][DIRECTIONS];
        double[][] stepZ = new double[steps][DIRECTIONS];
        for (int j = 0; j < steps; j++) {
            double r = distances[j];
            HeightMap map = pyramid.level(levelAt(r, level, pyramid.levelCount(), k -> pyramid.level(k).spacing()));
            levelAt[j] = map;
            scale[j] = d / map.spacing();
            shift[j] = map.size() / 2.0 - n / 2.0 * scale[j];
            inverse[j] = 1 / r;
            for (int m = 0; m < DIRECTIONS; m++) {
                stepX[j][m] = r * cos[m] / map.spacing();
                stepZ[j][m] = r * sin[m] / map.spacing();
            }
        }
        IntStream.range(0, n).parallel().forEach(row -> {
            double[] horizon = new double[DIRECTIONS];
            for (int col = 0; col < n; col++) {
                float h0 = grid.sample(col, row);
                double gx = (grid.sample(col + 1, row) - grid.sample(col - 1, row)) / (2 * d);
                double gz = (grid.sample(col, row + 1) - grid.sample(col, row - 1)) / (2 * d);
                Arrays.fill(horizon, Double.NEGATIVE_INFINITY);
                for (int j = 0; j < steps; j++) {
                    double x = col * scale[j] + shift[j];
                    double z = row * scale[j] + shift[j];
                    for (int m = 0; m < DIRECTIONS; m++) {
                        double rise = (bilinear(levelAt[j], x + stepX[j][m], z + stepZ[j][m]) - h0) * inverse[j];
                        horizon[m] = Math.max(horizon[m], rise);
                    }
                }
                double sum = 0;
                for (int m = 0; m < DIRECTIONS; m++) {
                    sum += visibleShare(horizon[m], gx * cos[m] + gz * sin[m]);
                }
                values[row * n + col] = (byte) Math.round(255 * sum / DIRECTIONS);
            }
        });
        return new SkyVisibility(n, d, values, grid.periodic());
    }

    /**
     * The distances at which the horizon is searched from a grid of samples {@code d} metres apart:
     * {@code d · STEP_GROWTH^j} for j = 0, 1, ... while under {@link #REACH_METRES}, and the first beyond.
     */
    public static double[] distances(double d) {
        int steps = Math.max(0, (int) Math.ceil(Math.log(REACH_METRES / d) / Math.log(STEP_GROWTH)) + 1);
        double[] r = new double[steps];
        for (int j = 0; j < steps; j++) {
            r[j] = d * Math.pow(STEP_GROWTH, j);
        }
        return r;
    }

    /**
     * The level read at distance {@code r}: from {@code from}, the coarsest of the {@code count} levels whose samples
     * lie at most {@code r / LEVEL_SPAN} apart ({@code spacing} gives a level's, growing with the level).
     */
    public static int levelAt(double r, int from, int count, IntToDoubleFunction spacing) {
        int k = from;
        while (k + 1 < count && spacing.applyAsDouble(k + 1) <= r / LEVEL_SPAN) {
            k++;
        }
        return k;
    }

    /**
     * The visibility at the samples of a map of the same extent, {@code n} at least this map's samples per side (a
     * power-of-two multiple), interpolated bilinearly: sample i of the finer map lies at coordinate i / f of this one.
     */
    public byte[] resampled(int n) {
        int f = n / size;
        if (f * size != n) {
            throw new IllegalArgumentException("resampling " + size + " samples to " + n);
        }
        byte[] out = new byte[n * n];
        for (int row = 0; row < n; row++) {
            int r0 = row / f;
            float fz = (float) (row % f) / f;
            for (int col = 0; col < n; col++) {
                int c0 = col / f;
                float fx = (float) (col % f) / f;
                float top = raw(c0, r0) + (raw(c0 + 1, r0) - raw(c0, r0)) * fx;
                float bottom = raw(c0, r0 + 1) + (raw(c0 + 1, r0 + 1) - raw(c0, r0 + 1)) * fx;
                out[row * n + col] = (byte) Math.round(top + (bottom - top) * fz);
            }
        }
        return out;
    }

    /** The visibility at world position (x, z), metres, 0..1 in steps of 1/255, at the nearest sample. */
    public double visibleAt(double x, double z) {
        return raw((int) Math.round(x / spacing + size / 2.0), (int) Math.round(z / spacing + size / 2.0)) / 255.0;
    }

    /** The stored byte at (col, row), wrapped or clamped like the heights. */
    private int raw(int col, int row) {
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

package org.openworld.engine.shadow;

/**
 * Where the view frustum is cut into cascades: the view distances that bound each cascade's slice.
 *
 * <p>One shadow map over the whole view range spends as many texels on a far mountain as on the ground at the
 * camera's feet, so near shadows are blocky (the paper's aliasing, section 3.2). Cascades give each slice of the view
 * range its own map. The best cut makes a texel's size on screen the same in every slice: the projected size of a
 * texel grows with the distance {@code d}, so the slices should grow geometrically, {@code d_i = n·(f/n)^(i/c)}. That
 * logarithmic scheme makes the first slice very thin (with {@code n = 0.5 m}, {@code f = 1200 m}, {@code c = 4} the
 * first ends at 3.5 m), so the practical scheme of Zhang et al. (2006, "parallel-split shadow maps") blends it with
 * the uniform one.
 */
public final class CascadeSplits {

    private CascadeSplits() {
    }

    /**
     * Practical split scheme (Zhang et al. 2006, "parallel-split shadow maps"):
     * {@code d_i = λ·n·(f/n)^(i/c) + (1−λ)·(n + (f−n)·i/c)}, {@code i = 0..c}. The blend {@code λ} runs from 0, uniform
     * (equal steps: the far slices are as sharp as the near ones, which wastes texels far away), to 1, logarithmic (a
     * constant ratio between neighbours: the same on-screen texel size in every slice, but a near slice that covers
     * almost nothing). Both terms grow strictly with {@code i}, so every blend does; the ends are set exactly.
     *
     * @param near  the view distance where the first slice starts, metres, {@code > 0} (the log term needs it)
     * @param far   where the last slice ends, metres, {@code > near}
     * @param count the number of cascades {@code c}, at least 1
     * @param blend {@code λ}, 0 (uniform) to 1 (logarithmic)
     * @return {@code c + 1} distances in metres, {@code d_0 = near}, {@code d_c = far}, strictly increasing
     * @throws IllegalArgumentException naming the bad value, also when {@code far − near} is too small for the doubles
     *                                  between them to give {@code c} distinct steps
     */
    public static double[] distances(double near, double far, int count, double blend) {
        if (!(near > 0) || !Double.isFinite(near)) {
            throw new IllegalArgumentException("near must be a finite distance > 0 m, got " + near);
        }
        if (!(far > near) || !Double.isFinite(far)) {
            throw new IllegalArgumentException("far must be finite and > near (" + near + " m), got " + far);
        }
        if (count < 1) {
            throw new IllegalArgumentException("count must be at least 1 cascade, got " + count);
        }
        if (!(blend >= 0 && blend <= 1)) {
            throw new IllegalArgumentException("blend must be in 0..1 (0 uniform, 1 logarithmic), got " + blend);
        }
        double[] d = new double[count + 1];
        d[0] = near;
        d[count] = far;
        for (int i = 1; i < count; i++) {
            double t = (double) i / count;
            double logarithmic = near * Math.pow(far / near, t);
            double uniform = near + (far - near) * t;
            d[i] = blend * logarithmic + (1 - blend) * uniform;
        }
        for (int i = 1; i <= count; i++) {
            if (!(d[i] > d[i - 1])) {
                throw new IllegalArgumentException("far (" + far + " m) is too close to near (" + near
                        + " m) for " + count + " distinct cascades");
            }
        }
        return d;
    }
}

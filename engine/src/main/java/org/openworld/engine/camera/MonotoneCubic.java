package org.openworld.engine.camera;

/**
 * Monotone piecewise cubic Hermite interpolation of one value over time, the method of MATLAB's {@code pchip}
 * (Fritsch and Carlson, SIAM J. Numer. Anal. 1980; tangents of Fritsch and Butland, SIAM J. Sci. Stat. Comput. 1984).
 *
 * <p>Between keys (t_i, v_i) and (t_{i+1}, v_{i+1}), with h = t_{i+1} - t_i and s = (t - t_i) / h, the value is the
 * cubic Hermite polynomial
 * <pre>
 *   v(s) = (2s³ - 3s² + 1) v_i + (s³ - 2s² + s) h m_i + (-2s³ + 3s²) v_{i+1} + (s³ - s²) h m_{i+1}
 * </pre>
 * With the slopes d_i = (v_{i+1} - v_i) / h_i on either side of a key, its tangent is
 * <pre>
 *   m_k = 0                                                         if d_{k-1} and d_k differ in sign or one is 0
 *   m_k = 3 (h_{k-1} + h_k) / ((2h_k + h_{k-1}) / d_{k-1} + (h_k + 2h_{k-1}) / d_k)     otherwise
 * </pre>
 * a weighted harmonic mean that never exceeds three times the smaller slope, which keeps every segment monotone.
 * The end keys take the slope of their one segment.
 *
 * <p>Why not Catmull–Rom for angles: its tangents ignore where the motion reverses, so a camera that turns right
 * to a key and then left swings past the key first; with uneven key times the swing is large (15° past a 20° turn
 * in the tests). This curve is just as smooth where the turn keeps its direction and never passes a key's value, so a
 * pitch stays within the keys' limits.
 */
final class MonotoneCubic {

    private MonotoneCubic() {
    }

    /**
     * The curve through (knots[k], values[k]) at t.
     *
     * @param knots   strictly increasing, at least two
     * @param segment i with knots[i] &lt;= t &lt;= knots[i + 1]
     */
    static double interpolate(double[] knots, double[] values, int segment, double t) {
        int i = segment;
        double h = knots[i + 1] - knots[i];
        double s = (t - knots[i]) / h;
        double s2 = s * s;
        double s3 = s2 * s;
        return (2 * s3 - 3 * s2 + 1) * values[i] + (s3 - 2 * s2 + s) * h * tangent(knots, values, i)
                + (-2 * s3 + 3 * s2) * values[i + 1] + (s3 - s2) * h * tangent(knots, values, i + 1);
    }

    private static double tangent(double[] knots, double[] values, int k) {
        int last = knots.length - 1;
        if (k == 0) {
            return slope(knots, values, 0);
        }
        if (k == last) {
            return slope(knots, values, last - 1);
        }
        double before = slope(knots, values, k - 1);
        double after = slope(knots, values, k);
        if (before * after <= 0) {
            return 0;
        }
        double hBefore = knots[k] - knots[k - 1];
        double hAfter = knots[k + 1] - knots[k];
        return 3 * (hBefore + hAfter) / ((2 * hAfter + hBefore) / before + (hAfter + 2 * hBefore) / after);
    }

    private static double slope(double[] knots, double[] values, int i) {
        return (values[i + 1] - values[i]) / (knots[i + 1] - knots[i]);
    }
}

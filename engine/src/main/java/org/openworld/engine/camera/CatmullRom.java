package org.openworld.engine.camera;

import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * Catmull–Rom interpolation: a smooth curve that passes through its control points, evaluated with the
 * Barry–Goldman pyramid (Barry and Goldman, "A recursive evaluation algorithm for a class of Catmull–Rom splines",
 * SIGGRAPH 1988).
 *
 * <h2>The pyramid</h2>
 * Four control points P0..P3 with increasing knots t0 &lt; t1 &lt; t2 &lt; t3 define the segment from P1 (at t1) to
 * P2 (at t2). Three rounds of linear interpolation, each line drawn between two knots, give the point at t:
 * <pre>
 *   A1 = (t1 - t)/(t1 - t0) P0 + (t - t0)/(t1 - t0) P1
 *   A2 = (t2 - t)/(t2 - t1) P1 + (t - t1)/(t2 - t1) P2
 *   A3 = (t3 - t)/(t3 - t2) P2 + (t - t2)/(t3 - t2) P3
 *   B1 = (t2 - t)/(t2 - t0) A1 + (t - t0)/(t2 - t0) A2
 *   B2 = (t3 - t)/(t3 - t1) A2 + (t - t1)/(t3 - t1) A3
 *   C  = (t2 - t)/(t2 - t1) B1 + (t - t1)/(t2 - t1) B2
 * </pre>
 * At t = t1 every weight that does not lead to P1 is zero, so C = P1; likewise C = P2 at t2. Neighbouring segments
 * share their tangents at the joint, so a chain of segments is C1 in the knot parameter.
 *
 * <h2>The knots</h2>
 * The knots are spaced by the distance between points raised to a power alpha:
 * <pre>
 *   t_{i+1} = t_i + |P_{i+1} - P_i|^alpha
 * </pre>
 * alpha = 0 is the uniform spline, alpha = 1 the chordal one, alpha = 0.5 the <em>centripetal</em> one.
 * Yuksel, Schaefer and Keyser ("Parameterization and applications of Catmull–Rom curves", CAD 2011) prove that the
 * centripetal spline never forms a cusp or a loop inside a segment and stays close to its control polygon; the
 * uniform spline overshoots and loops where neighbouring points are unevenly spaced, which for a camera means
 * a sudden swerve between two keys.
 *
 * <p>Two coincident points would give a zero knot interval and a division by zero, so each interval is at least
 * {@link #MIN_KNOT_INTERVAL}. A raised interval only ever lies between points closer than its square, so the large
 * weight it produces multiplies a tiny difference and the result stays finite, next to the coincident points.
 */
public final class CatmullRom {

    /** The knot exponent of the centripetal spline: no cusps, no self-intersections within a segment. */
    public static final double CENTRIPETAL_ALPHA = 0.5;

    /** Smallest knot interval, √metres: points closer than its square (1e-12 m) count as coincident. */
    static final double MIN_KNOT_INTERVAL = 1e-6;

    private CatmullRom() {
    }

    /**
     * The point on the centripetal segment from {@code p1} to {@code p2}.
     *
     * @param u    where along the segment, 0 at {@code p1} and 1 at {@code p2}, mapped linearly onto the knot interval
     *             [t1, t2]
     * @param dest receives the point
     * @return {@code dest}
     */
    public static Vector3d centripetal(Vector3dc p0, Vector3dc p1, Vector3dc p2, Vector3dc p3, double u,
                                       Vector3d dest) {
        double t0 = 0;
        double t1 = t0 + knotInterval(p0, p1);
        double t2 = t1 + knotInterval(p1, p2);
        double t3 = t2 + knotInterval(p2, p3);
        double t = t1 + u * (t2 - t1);
        return dest.set(
                interpolate(p0.x(), p1.x(), p2.x(), p3.x(), t0, t1, t2, t3, t),
                interpolate(p0.y(), p1.y(), p2.y(), p3.y(), t0, t1, t2, t3, t),
                interpolate(p0.z(), p1.z(), p2.z(), p3.z(), t0, t1, t2, t3, t));
    }

    /**
     * The Barry–Goldman pyramid for one coordinate, with any increasing knots.
     *
     * @param t0 knot of {@code p0}; the knots must increase strictly
     * @param t  where to evaluate, within [t1, t2]
     * @return the curve's value at {@code t}: {@code p1} at t1, {@code p2} at t2
     */
    static double interpolate(double p0, double p1, double p2, double p3,
                                     double t0, double t1, double t2, double t3, double t) {
        double a1 = line(p0, p1, t0, t1, t);
        double a2 = line(p1, p2, t1, t2, t);
        double a3 = line(p2, p3, t2, t3, t);
        double b1 = line(a1, a2, t0, t2, t);
        double b2 = line(a2, a3, t1, t3, t);
        return line(b1, b2, t1, t2, t);
    }

    /** |b - a|^alpha for the centripetal alpha, never less than {@link #MIN_KNOT_INTERVAL}. */
    private static double knotInterval(Vector3dc a, Vector3dc b) {
        return Math.max(Math.pow(a.distance(b), CENTRIPETAL_ALPHA), MIN_KNOT_INTERVAL);
    }

    /** The line through (ta, a) and (tb, b) evaluated at t. */
    private static double line(double a, double b, double ta, double tb, double t) {
        return ((tb - t) * a + (t - ta) * b) / (tb - ta);
    }
}

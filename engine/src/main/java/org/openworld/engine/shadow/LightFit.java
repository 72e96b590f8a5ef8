package org.openworld.engine.shadow;

import org.joml.Matrix4d;
import org.joml.Matrix4f;
import org.joml.Matrix4fc;
import org.joml.Vector3d;
import org.joml.Vector3fc;

/**
 * Fits a cascade's orthographic light box around a slice of the view frustum: the part between view distances
 * {@code from} and {@code to}, measured along the view axis (view-space {@code −z}). Two fits:
 * <ul>
 *   <li>{@link #stable} (the default, for cascaded maps): a fixed-size square around the slice's bounding sphere whose
 *       texel grid is pinned to the world, so shadow edges stand still as the camera moves and turns;</li>
 *   <li>{@link #covering} (the paper's, section 3.2): the tight box around the slice's corners. It spends every texel
 *       on what the camera sees, but its size and grid follow the camera, so shadow edges crawl ("swim") as it moves.</li>
 * </ul>
 * Both extend the box by {@code reach} metres towards the sun, so that casters between the slice and the sun (a
 * mountain) are drawn into the map.
 *
 * <p><b>Where the box lives.</b> The light's view is the rotation {@link #lightRotation} alone ({@code +Z} towards the
 * sun, {@code +Y} the world's up as seen from the sun, no translation): light space is the world turned to face the
 * sun. The box's place is all in the orthographic projection, whose bounds are light-space coordinates. So a moving
 * box changes only the projection's translation column, and in {@code projection · view} that column is the
 * projection's own, not a float product: the stable fit's snapped offset, a whole number of texels of
 * {@code 2 / resolution} clip units each, is then held exactly in float (for a power-of-two resolution) however far
 * from the origin the camera is. Matrices are built in double precision and rounded to float once.
 */
public final class LightFit {

    /**
     * Half-angle of the cone around the vertical in which the world's up is too close to the sun's direction to give
     * the light's up (radians; 8°, so the cross product in {@link #lightRotation} keeps at least sin 8° ≈ 0.14 of its
     * length and never loses precision).
     */
    private static final double ZENITH_CONE = Math.toRadians(8);
    /** How far {@code |toSun|} may be from 1 (unitless): far above float rounding (1e-7), far below a real mistake. */
    private static final double UNIT_TOLERANCE = 1e-3;

    private LightFit() {
    }

    /**
     * The stable fit (the default, cascaded maps): a square box around the slice's bounding sphere (radius
     * {@link #sliceRadius} {@code r}, centre on the view axis), whose size depends only on {@code from}, {@code to}
     * and the projection's field of view, so it does not change as the camera turns. Its centre, in light space, is
     * moved to a whole number of texels, so that as the camera moves the map's texel grid stays fixed in the world and
     * shadow edges do not swim: a world point keeps its place inside its texel. The depth is also snapped to whole
     * texels, so a still point keeps its depth too.
     *
     * <p>Snapping moves the centre by up to half a texel in each axis, which would push the sphere's edge out of a box
     * of half-size {@code r}. So the sphere is given {@code resolution − 1} texels and the half texel on each side is
     * the snap's room: half-size {@code h = r · resolution / (resolution − 1)}, texel {@code t = 2h / resolution}
     * (then {@code h − r = t / 2}). Box, in light space: {@code x, y ∈ [−h, h]} around the snapped centre; depth from
     * {@code h + reach} on the sun's side to {@code h} on the far side. Built as JOML's {@code setOrtho(−h, h, −h, h, …)}
     * and then {@code translateLocal} by the snapped centre's whole texels in clip space.
     *
     * @param view       the view camera's world → view matrix
     * @param projection its perspective projection (JOML {@code perspective}: symmetric)
     * @param from       where the slice starts, view distance in metres, {@code > 0}
     * @param to         where it ends, metres, {@code > from}
     * @param toSun      unit world vector towards the sun
     * @param reach      metres beyond the slice, towards the sun, in which casters are drawn, {@code ≥ 0}
     * @param resolution shadow-map texels per side, at least 2 (the snap needs a spare texel)
     */
    public static LightBox stable(Matrix4fc view, Matrix4fc projection, double from, double to, Vector3fc toSun,
                                  double reach, int resolution) {
        requireSlice(from, to);
        requireSun(toSun);
        requireReach(reach);
        if (resolution < 2) {
            throw new IllegalArgumentException("resolution must be at least 2 texels for the stable fit (one texel is"
                    + " the snap's room), got " + resolution);
        }
        double k2 = diagonalSlope2(projection);
        double centreDistance = centreDistance(k2, from, to);
        double half = radius(k2, from, to, centreDistance) * resolution / (resolution - 1);
        double texel = 2 * half / resolution;
        Matrix4f rotation = lightRotation(toSun);
        Vector3d centre = new Matrix4d(view).invertAffine().transformPosition(new Vector3d(0, 0, -centreDistance));
        new Matrix4d(rotation).transformPosition(centre);
        // 1. Snap the centre to whole texels, in the light's plane and in depth.
        double texelsX = Math.rint(centre.x / texel);
        double texelsY = Math.rint(centre.y / texel);
        double sunward = Math.rint(centre.z / texel) * texel + half + reach;
        // 2. A box of half-size h around the light-space origin, then moved by whole texels in clip space: 2/resolution
        //    clip units per texel, exact in float for a power-of-two resolution.
        Matrix4d box = new Matrix4d().setOrtho(-half, half, -half, half, -sunward, 2 * half + reach - sunward)
                .translateLocal(-2 * texelsX / resolution, -2 * texelsY / resolution, 0);
        return new LightBox(rotation, new Matrix4f(box), (float) texel, (float) (2 * half + reach));
    }

    /**
     * The paper's fit: the tight light-space bounding box of the slice's 8 corners (x, y, and depth extended by
     * {@code reach} towards the sun), unsnapped: it covers exactly what the camera sees and changes shape as the camera
     * turns, and its texel grid slides with the camera as it moves. Texel size: the larger side over
     * {@code resolution}.
     *
     * @param resolution shadow-map texels per side, at least 1
     * @see #stable for the other parameters
     */
    public static LightBox covering(Matrix4fc view, Matrix4fc projection, double from, double to, Vector3fc toSun,
                                    double reach, int resolution) {
        requireSlice(from, to);
        requireSun(toSun);
        requireReach(reach);
        if (resolution < 1) {
            throw new IllegalArgumentException("resolution must be at least 1 texel, got " + resolution);
        }
        Matrix4f rotation = lightRotation(toSun);
        Matrix4d toLight = new Matrix4d(rotation);
        Vector3d min = new Vector3d(Double.POSITIVE_INFINITY);
        Vector3d max = new Vector3d(Double.NEGATIVE_INFINITY);
        for (Vector3d corner : sliceCorners(view, projection, from, to)) {
            toLight.transformPosition(corner);
            min.min(corner);
            max.max(corner);
        }
        double sunward = max.z + reach;
        double texel = Math.max(max.x - min.x, max.y - min.y) / resolution;
        Matrix4d box = new Matrix4d().setOrtho(min.x, max.x, min.y, max.y, -sunward, -min.z);
        return new LightBox(rotation, new Matrix4f(box), (float) texel, (float) (sunward - min.z));
    }

    /**
     * Radius of the smallest sphere around a symmetric perspective slice from view distance {@code n = from} to
     * {@code f = to}.
     *
     * <p>Derivation. At view distance {@code d} the slice's cross-section is the rectangle {@code x = ±d/P00},
     * {@code y = ±d/P11}, whose corners lie {@code k·d} from the axis, {@code k² = 1/P00² + 1/P11²} ({@code k} is the
     * tangent of the half-diagonal angle). The slice is symmetric under {@code x → −x} and {@code y → −y}, and the
     * smallest enclosing sphere is unique, so its centre lies on the axis, at some distance {@code z}. From there every
     * corner at distance {@code d} is {@code sqrt((z − d)² + k²d²)} away, so the radius is the larger of the near and
     * far corners' distances, {@code (z − n)² + k²n²} and {@code (f − z)² + k²f²} (squared). The first grows with
     * {@code z}, the second falls until {@code z = f}: the smallest maximum is where they are equal,
     * {@code 2z(f − n) = (1 + k²)(f² − n²)}, that is {@code z* = (1 + k²)(n + f)/2}, radius
     * {@code sqrt((z* − n)² + k²n²)}. When {@code z* ≥ f} (a wide or short slice) the far rectangle alone sets the
     * sphere: centre {@code z* = f}, radius {@code k·f}, which then also holds the near corners.
     *
     * <p>The radius depends only on {@code from}, {@code to}, {@code P00} and {@code P11}: not on where the camera is
     * or which way it looks, which is what keeps the stable fit's box the same size from frame to frame.
     *
     * @param projection a symmetric perspective projection (JOML {@code perspective})
     */
    public static double sliceRadius(Matrix4fc projection, double from, double to) {
        requireSlice(from, to);
        double k2 = diagonalSlope2(projection);
        return radius(k2, from, to, centreDistance(k2, from, to));
    }

    /**
     * World → light rotation: light {@code −Z} = {@code −toSun} (the light looks away from the sun), light {@code +Y} =
     * the world's up projected onto the light's plane, light {@code +X = Y × Z}. When the sun is within
     * 8° of the zenith (or the nadir) world {@code −Z} (north) serves as "up" instead, so the basis
     * never degenerates. JOML's {@code setLookAlong(−toSun, up)} builds exactly this. It depends on the sun alone, so
     * it stays fixed while the sun is still: the stable fit's snapping relies on that.
     *
     * @param toSun unit world vector towards the sun
     */
    public static Matrix4f lightRotation(Vector3fc toSun) {
        requireSun(toSun);
        boolean nearZenith = Math.abs(toSun.y()) > Math.cos(ZENITH_CONE);
        float upY = nearZenith ? 0 : 1;
        float upZ = nearZenith ? -1 : 0;
        return new Matrix4f().setLookAlong(-toSun.x(), -toSun.y(), -toSun.z(), 0, upY, upZ);
    }

    /**
     * The slice's 8 world corners: the 4 at view distance {@code from} (x−y−, x+y−, x−y+, x+y+), then the 4 at
     * {@code to}. View-space corner {@code (±d/P00, ±d/P11, −d)} taken through the view's inverse, in double precision.
     */
    static Vector3d[] sliceCorners(Matrix4fc view, Matrix4fc projection, double from, double to) {
        requireSlice(from, to);
        requirePerspective(projection);
        Matrix4d toWorld = new Matrix4d(view).invertAffine();
        Vector3d[] corners = new Vector3d[8];
        for (int i = 0; i < 8; i++) {
            double d = i < 4 ? from : to;
            double x = ((i & 1) == 0 ? -d : d) / projection.m00();
            double y = ((i & 2) == 0 ? -d : d) / projection.m11();
            corners[i] = toWorld.transformPosition(new Vector3d(x, y, -d));
        }
        return corners;
    }

    /** On-axis distance of the bounding sphere's centre: {@code z* = min(f, (1 + k²)(n + f)/2)}. */
    private static double centreDistance(double k2, double from, double to) {
        return Math.min(to, (1 + k2) * (from + to) / 2);
    }

    private static double radius(double k2, double from, double to, double centreDistance) {
        if (centreDistance < to) {
            double dz = centreDistance - from;
            return Math.sqrt(dz * dz + k2 * from * from);
        }
        return Math.sqrt(k2) * to;
    }

    /** {@code k² = 1/P00² + 1/P11²}, the squared tangent of the projection's half-diagonal angle. */
    private static double diagonalSlope2(Matrix4fc projection) {
        requirePerspective(projection);
        double p00 = projection.m00();
        double p11 = projection.m11();
        return 1 / (p00 * p00) + 1 / (p11 * p11);
    }

    /** The x and y scales a symmetric perspective has: finite and positive. */
    private static void requirePerspective(Matrix4fc projection) {
        float p00 = projection.m00();
        float p11 = projection.m11();
        if (!(p00 > 0 && p11 > 0) || !Float.isFinite(p00) || !Float.isFinite(p11)) {
            throw new IllegalArgumentException("projection must be a perspective with P00, P11 > 0, got P00 = " + p00
                    + ", P11 = " + p11);
        }
    }

    private static void requireSlice(double from, double to) {
        if (!(from > 0) || !Double.isFinite(from)) {
            throw new IllegalArgumentException("from must be a finite view distance > 0 m, got " + from);
        }
        if (!(to > from) || !Double.isFinite(to)) {
            throw new IllegalArgumentException("to must be finite and > from (" + from + " m), got " + to);
        }
    }

    private static void requireSun(Vector3fc toSun) {
        if (toSun == null || !(Math.abs(toSun.length() - 1) <= UNIT_TOLERANCE)) {
            throw new IllegalArgumentException("toSun must be a unit vector, got " + toSun);
        }
    }

    private static void requireReach(double reach) {
        if (!(reach >= 0) || !Double.isFinite(reach)) {
            throw new IllegalArgumentException("reach must be a finite distance >= 0 m, got " + reach);
        }
    }
}

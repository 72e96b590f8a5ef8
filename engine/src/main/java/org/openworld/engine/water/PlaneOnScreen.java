package org.openworld.engine.water;

import org.joml.Matrix4f;
import org.joml.Matrix4fc;
import org.joml.Vector3f;
import org.joml.Vector3fc;
import org.joml.Vector4f;
import org.joml.Vector4fc;

/**
 * Where the water plane {@code y = level} lies on the screen, for an eye above it, in normalised device coordinates
 * (x, y in −1..1), so the water can be drawn as ordinary geometry that the depth test rejects early wherever the
 * terrain covers it.
 *
 * <p><b>Depth.</b> A projective map takes planes to planes, so the plane's NDC depth is an affine function of the
 * screen position: {@code z = depth.x · x + depth.y · y + depth.z}. The plane {@code (0, 1, 0, −level)} becomes
 * {@code (VP⁻¹)ᵀ · (0, 1, 0, −level)} in clip space, solved for z. A full-screen triangle whose corners carry these
 * depths is rasterised with the plane's exact depth at every pixel, no {@code gl_FragDepth} needed.
 *
 * <p><b>Horizon.</b> The plane through the eye parallel to the water, {@code (0, 1, 0, −eye.y)}, maps to a plane
 * that contains the projection centre and so is parallel to the z axis: the horizon line
 * {@code horizon.x · x + horizon.y · y + horizon.z = 0}. Its value at a pixel has the sign of {@code y − eye.y} of
 * the point seen there (divided by its clip w, positive in front of the eye); the sign is flipped here so the
 * water's side is positive, a clip distance that cuts the triangle at the horizon.
 *
 * <p><b>Bounds.</b> The screen square cut by the horizon line is a convex polygon of at most 5 corners; its bounding
 * rectangle is where the water can be seen at all (the reflection pass is scissored to it).
 *
 * @param depth   NDC depth of the plane: {@code z = depth · (x, y, 1)}
 * @param horizon the water's side of the horizon: {@code horizon · (x, y, 1) ≥ 0}
 * @param bounds  (xMin, yMin, xMax, yMax) of the water on the screen, NDC; xMin &gt; xMax when none is seen
 */
public record PlaneOnScreen(Vector3fc depth, Vector3fc horizon, Vector4fc bounds) {

    /**
     * @param viewProjection the camera's projection · view
     * @param eyeY           the eye's height, above {@code level}
     * @param level          the water plane's height
     */
    public static PlaneOnScreen of(Matrix4fc viewProjection, float eyeY, float level) {
        Matrix4f toNdcPlane = viewProjection.invert(new Matrix4f()).transpose();
        Vector4f water = toNdcPlane.transform(new Vector4f(0, 1, 0, -level));
        Vector4f eyePlane = toNdcPlane.transform(new Vector4f(0, 1, 0, -eyeY));
        Vector3f depth = new Vector3f(-water.x / water.z, -water.y / water.z, -water.w / water.z);
        Vector3f horizon = new Vector3f(-eyePlane.x, -eyePlane.y, -eyePlane.w);
        return new PlaneOnScreen(depth, horizon, bounds(horizon));
    }

    /** The bounding rectangle of the screen square's part on the positive side of the line (Sutherland–Hodgman). */
    private static Vector4f bounds(Vector3fc line) {
        float[][] corners = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        Vector4f box = new Vector4f(Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY,
                Float.NEGATIVE_INFINITY);
        for (int i = 0; i < 4; i++) {
            float[] a = corners[i];
            float[] b = corners[(i + 1) % 4];
            float da = side(line, a);
            float db = side(line, b);
            if (da >= 0) {
                include(box, a[0], a[1]);
            }
            if ((da < 0) != (db < 0)) {
                float t = da / (da - db);
                include(box, a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]));
            }
        }
        return box;
    }

    private static float side(Vector3fc line, float[] p) {
        return line.x() * p[0] + line.y() * p[1] + line.z();
    }

    private static void include(Vector4f box, float x, float y) {
        box.set(Math.min(box.x, x), Math.min(box.y, y), Math.max(box.z, x), Math.max(box.w, y));
    }

    /** Whether any water is on the screen. */
    public boolean visible() {
        return bounds.x() <= bounds.z() && bounds.y() <= bounds.w();
    }
}

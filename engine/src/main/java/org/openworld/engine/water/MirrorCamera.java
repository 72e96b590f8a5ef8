package org.openworld.engine.water;

import org.joml.Matrix4d;
import org.joml.Matrix4f;
import org.joml.Matrix4fc;
import org.joml.Vector3d;
import org.joml.Vector4d;
import org.joml.Vector4f;
import org.joml.Vector4fc;
import org.openworld.engine.core.ViewCamera;

/**
 * The reflection pass's camera: the viewer's camera mirrored in the water plane {@code y = h}, optionally with its
 * near plane moved onto the water (Lengyel's oblique near-plane clipping), so that nothing under the water is drawn
 * into the reflection. GL-free.
 *
 * <p><b>Mirror.</b> Reflecting in {@code y = h} maps {@code (x, y, z)} to {@code (x, 2h − y, z)}:
 * {@code M = T(0, h, 0) · S(1, −1, 1) · T(0, −h, 0)}. The mirrored view is {@code V · M}: a point {@code p} of the
 * world lands in the reflection where the viewer would see its mirror image {@code M p}, so the reflection picture
 * lines up with the screen, pixel for pixel, wherever the water is flat. {@code det M = −1}: the mirrored camera
 * flips handedness, which the engine answers by swapping the front-face winding (the paper's "cull front faces").
 *
 * <p><b>Oblique clip plane</b> (E. Lengyel, "Oblique View Frustum Depth Projection and Clipping", JGT 2005). A
 * clip plane {@code C} (view space, the eye on its negative side) replaces the near plane when the projection's
 * third row becomes {@code c − r₄}, with {@code c = C · 2 / (C · q)} and {@code q = P⁻¹ (sgn Cₓ, sgn C_y, 1, 1)}, the
 * frustum corner opposite the plane. Clip-space {@code z = −w} is then exactly the plane, so the GPU's own clipping
 * cuts at the water in every shader, and the frustum's near plane culls under-water patches. Cost: one 4×4
 * inverse per frame. Limits: the far plane tilts with the near one (geometry beyond the far corner is clipped;
 * at 40 km that is beyond the fog), depth precision is poorer near the water, and with the eye within
 * {@link #MIN_HEIGHT} of the water the plane passes through the eye and the projection degenerates.
 */
public final class MirrorCamera {

    /** Below this height of the eye above the water, metres, the oblique projection degenerates. */
    static final float MIN_HEIGHT = 0.05f;

    private MirrorCamera() {
    }

    /** The reflection in the plane {@code y = level}: {@code (x, y, z) → (x, 2·level − y, z)}. */
    public static Matrix4f reflection(float level) {
        return new Matrix4f().translate(0, level, 0).scale(1, -1, 1).translate(0, -level, 0);
    }

    /**
     * The projection whose near plane is {@code viewPlane} (view space; kept points have {@code C · p > 0}, and the
     * eye, the origin, must lie on the negative side: {@code C.w < 0}).
     */
    public static Matrix4f obliqueNearPlane(Matrix4fc projection, Vector4fc viewPlane) {
        if (viewPlane.w() >= 0) {
            throw new IllegalArgumentException("the oblique near plane must have the eye behind it, got " + viewPlane);
        }
        Vector4f q = new Matrix4f(projection).invert()
                .transform(new Vector4f(Math.signum(viewPlane.x()), Math.signum(viewPlane.y()), 1, 1));
        Vector4f c = new Vector4f(viewPlane).mul(2f / viewPlane.dot(q));
        return new Matrix4f(projection)
                .m02(c.x - projection.m03()).m12(c.y - projection.m13())
                .m22(c.z - projection.m23()).m32(c.w - projection.m33());
    }

    /**
     * The viewer mirrored in the water at {@code level}.
     *
     * @param clip true to clip at the water (the Fresnel method); false draws everything, as the paper's stencil
     *             method does, so what lies under the water shows in the reflection too
     */
    static ViewCamera of(ViewCamera viewer, float level, boolean clip) {
        Matrix4f mirror = reflection(level);
        Matrix4d exactView = new Matrix4d(viewer.exactView()).mul(new Matrix4d(mirror));
        Matrix4f view = new Matrix4f(exactView);
        Vector3d eye = new Matrix4d(mirror).transformPosition(new Vector3d(viewer.exactPosition()));
        Matrix4f projection = new Matrix4f(viewer.projection());
        if (clip) {
            // The plane y = level, kept side up, in the mirrored camera's view space: planes map by V^-T.
            // (in double: the view's translation is the eye's distance from the world's origin, thousands of km)
            Vector4d exactPlane = new Matrix4d(exactView).invert().transpose().transform(new Vector4d(0, 1, 0, -level));
            Vector4f plane = new Vector4f((float) exactPlane.x, (float) exactPlane.y, (float) exactPlane.z,
                    (float) exactPlane.w);
            projection = obliqueNearPlane(projection, plane);
        }
        return new ViewCamera(exactView, projection, eye, viewer.near(), viewer.far());
    }
}

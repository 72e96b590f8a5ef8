package org.openworld.engine.shadow;

import org.joml.Matrix4d;
import org.joml.Matrix4f;
import org.joml.Matrix4fc;
import org.joml.Vector3d;
import org.joml.Vector3f;

/**
 * One cascade's light camera: an orthographic box along the sun, made by {@link LightFit}. Immutable: the matrices
 * are copied in and copied out, so no caller can change a box another one holds.
 *
 * <p>The view's origin need not be the box's: {@link LightFit}'s boxes keep the view a pure rotation and put the box's
 * place into the projection (an off-centre ortho), see there why. {@link #sunwardCentre} gives the box's "eye".
 *
 * @param view       world → light space: a rotation and a translation (determinant +1), looking along {@code −toSun},
 *                   so light-space {@code −Z} points away from the sun and {@code +Z} towards it
 * @param projection JOML {@code ortho} (OpenGL clip, depth −1..1): the box's sides, in light-space coordinates
 * @param texelSize  metres per shadow-map texel, of the larger side for a non-square box: how coarse the shadows are
 * @param depthRange metres from the box's near (sunward) plane to its far plane: what the depth buffer's bits share
 */
public record LightBox(Matrix4fc view, Matrix4fc projection, float texelSize, float depthRange) {

    public LightBox {
        if (view == null || projection == null) {
            throw new IllegalArgumentException("view and projection must be given, got " + view + ", " + projection);
        }
        if (!(texelSize > 0) || !Float.isFinite(texelSize)) {
            throw new IllegalArgumentException("texelSize must be a finite size > 0 m, got " + texelSize);
        }
        if (!(depthRange > 0) || !Float.isFinite(depthRange)) {
            throw new IllegalArgumentException("depthRange must be a finite length > 0 m, got " + depthRange);
        }
        view = new Matrix4f(view);
        projection = new Matrix4f(projection);
    }

    /** A copy of the world → light matrix. */
    @Override
    public Matrix4fc view() {
        return new Matrix4f(view);
    }

    /** A copy of the light → clip matrix. */
    @Override
    public Matrix4fc projection() {
        return new Matrix4f(projection);
    }

    /** A new matrix {@code projection · view}: world → the shadow map's clip space, what the shadow pass draws with. */
    public Matrix4f viewProjection() {
        return new Matrix4f(projection).mul(view);
    }

    /**
     * The world position of the centre of the box's near (sunward) face, for a {@link
     * org.openworld.engine.core.ViewCamera}'s position: the light camera's "eye". Clip {@code (0, 0, −1)} taken back
     * through the projection's inverse into light space, then through the view's inverse into the world, in double
     * precision so a box far from the origin keeps its centimetres.
     */
    public Vector3f sunwardCentre() {
        Vector3d light = new Matrix4d(projection).invert().transformProject(new Vector3d(0, 0, -1));
        Vector3d world = new Matrix4d(view).invertAffine().transformPosition(light);
        return new Vector3f((float) world.x, (float) world.y, (float) world.z);
    }
}

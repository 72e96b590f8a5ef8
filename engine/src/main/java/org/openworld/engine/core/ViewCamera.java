package org.openworld.engine.core;

import org.joml.Matrix4d;
import org.joml.Matrix4dc;
import org.joml.Matrix4f;
import org.joml.Matrix4fc;
import org.joml.Vector3d;
import org.joml.Vector3dc;
import org.joml.Vector3f;
import org.joml.Vector3fc;
import org.openworld.engine.camera.CameraPose;

/**
 * The camera one pass renders with: view and projection matrices and the eye position. Immutable. A camera may be
 * <em>mirrored</em> (its view has a negative determinant, as the water's reflection camera does): it sees the world
 * with its handedness flipped, so triangles wind the other way on screen and the engine swaps which winding is the
 * front face. A clip plane, where a pass needs one, is built into the projection as its near plane (the water's
 * oblique projection), so every shader and the culling obey it without knowing of it.
 *
 * <p>View matrix from a pose, in docs/design.md's conventions (yaw clockwise from north = −Z, pitch up):
 * {@code V = Rx(−pitch) · Ry(yaw) · T(−eye)}. With yaw 90° that maps east (+X) onto the view direction −Z.
 *
 * <p>The view and the eye are also kept in double ({@link #exactView}, {@link #exactPosition}): far from the origin a
 * float eye is metres off (24 bits: 1 m at 10 000 km), and the GPU takes the view from the render origin
 * ({@link #viewFrom}), built from the double one.
 */
public final class ViewCamera {

    private final Matrix4f view;
    private final Matrix4d exactView;
    private final Vector3d exactPosition;
    private final Matrix4f projection;
    private final Matrix4f viewProjection;
    private final Vector3f position;
    private final float near;
    private final float far;

    public ViewCamera(Matrix4fc view, Matrix4fc projection, Vector3fc position, float near, float far) {
        this(new Matrix4d(view), projection, new Vector3d(position), near, far);
    }

    /** A camera whose view and eye are known in double (the viewer's, its mirror image). */
    public ViewCamera(Matrix4dc view, Matrix4fc projection, Vector3dc position, float near, float far) {
        this.exactView = new Matrix4d(view);
        this.exactPosition = new Vector3d(position);
        this.view = new Matrix4f(view);
        this.projection = new Matrix4f(projection);
        this.viewProjection = new Matrix4f(projection).mul(this.view);
        this.position = new Vector3f(position);  // JOML rounds each double to float
        this.near = near;
        this.far = far;
    }

    /** A perspective camera at a pose; {@code aspect} is width / height. */
    public static ViewCamera perspective(CameraPose pose, float aspect, float near, float far) {
        Vector3d eye = new Vector3d(pose.x(), pose.y(), pose.z());
        Matrix4d view = new Matrix4d()
                .rotateX(Math.toRadians(-pose.pitch()))
                .rotateY(Math.toRadians(pose.yaw()))
                .translate(-eye.x, -eye.y, -eye.z);
        Matrix4f projection = new Matrix4f().perspective((float) Math.toRadians(pose.fov()), aspect, near, far);
        return new ViewCamera(view, projection, eye, near, far);
    }

    public Matrix4fc view() {
        return view;
    }

    /** The view in double. */
    public Matrix4dc exactView() {
        return exactView;
    }

    /** The eye in double, metres. */
    public Vector3dc exactPosition() {
        return exactPosition;
    }

    /**
     * The view as the GPU takes it, from the render origin (x, 0, z): {@code V · T(origin)}, multiplied in double
     * and rounded to float once, so its translation is the eye's few metres from the origin, not the eye's
     * thousands of kilometres from the world's.
     */
    public Matrix4f viewFrom(double originX, double originZ) {
        return new Matrix4f(new Matrix4d(exactView).translate(originX, 0, originZ));
    }

    /** The eye from the render origin, metres, rounded to float once. */
    public Vector3f positionFrom(double originX, double originZ) {
        return new Vector3f((float) (exactPosition.x - originX), (float) exactPosition.y,
                (float) (exactPosition.z - originZ));
    }

    public Matrix4fc projection() {
        return projection;
    }

    public Matrix4fc viewProjection() {
        return viewProjection;
    }

    public Vector3fc position() {
        return position;
    }

    public float near() {
        return near;
    }

    public float far() {
        return far;
    }

    /** Whether the view flips handedness (a mirror's camera): counter-clockwise triangles then appear clockwise. */
    public boolean mirrored() {
        return view.determinant3x3() < 0;
    }
}

package org.openworld.engine.core;

import org.joml.Matrix4f;
import org.joml.Matrix4fc;
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
 */
public final class ViewCamera {

    private final Matrix4f view;
    private final Matrix4f projection;
    private final Matrix4f viewProjection;
    private final Vector3f position;
    private final float near;
    private final float far;

    public ViewCamera(Matrix4fc view, Matrix4fc projection, Vector3fc position, float near, float far) {
        this.view = new Matrix4f(view);
        this.projection = new Matrix4f(projection);
        this.viewProjection = new Matrix4f(projection).mul(view);
        this.position = new Vector3f(position);
        this.near = near;
        this.far = far;
    }

    /** A perspective camera at a pose; {@code aspect} is width / height. */
    public static ViewCamera perspective(CameraPose pose, float aspect, float near, float far) {
        Vector3f eye = new Vector3f((float) pose.x(), (float) pose.y(), (float) pose.z());
        Matrix4f view = new Matrix4f()
                .rotateX((float) Math.toRadians(-pose.pitch()))
                .rotateY((float) Math.toRadians(pose.yaw()))
                .translate(-eye.x, -eye.y, -eye.z);
        Matrix4f projection = new Matrix4f().perspective((float) Math.toRadians(pose.fov()), aspect, near, far);
        return new ViewCamera(view, projection, eye, near, far);
    }

    public Matrix4fc view() {
        return view;
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

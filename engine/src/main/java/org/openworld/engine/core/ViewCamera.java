package org.openworld.engine.core;

import org.joml.Matrix4f;
import org.joml.Matrix4fc;
import org.joml.Vector3f;
import org.joml.Vector3fc;
import org.joml.Vector4f;
import org.joml.Vector4fc;
import org.openworld.engine.camera.CameraPose;

/**
 * The camera one pass renders with: view and projection matrices, the eye position and an optional world-space
 * clip plane (the water's reflection pass clips everything below the water). Immutable.
 *
 * <p>View matrix from a pose, in DESIGN.md's conventions (yaw clockwise from north = −Z, pitch up):
 * {@code V = Rx(−pitch) · Ry(yaw) · T(−eye)}. With yaw 90° that maps east (+X) onto the view direction −Z.
 */
public final class ViewCamera {

    /** No clipping: every point has a positive distance. */
    public static final Vector4fc NO_CLIP = new Vector4f(0, 0, 0, 1);

    private final Matrix4f view;
    private final Matrix4f projection;
    private final Matrix4f viewProjection;
    private final Vector3f position;
    private final float near;
    private final float far;
    private final Vector4f clipPlane;

    public ViewCamera(Matrix4fc view, Matrix4fc projection, Vector3fc position, float near, float far, Vector4fc clipPlane) {
        this.view = new Matrix4f(view);
        this.projection = new Matrix4f(projection);
        this.viewProjection = new Matrix4f(projection).mul(view);
        this.position = new Vector3f(position);
        this.near = near;
        this.far = far;
        this.clipPlane = new Vector4f(clipPlane);
    }

    /** A perspective camera at a pose; {@code aspect} is width / height. */
    public static ViewCamera perspective(CameraPose pose, float aspect, float near, float far) {
        Vector3f eye = new Vector3f((float) pose.x(), (float) pose.y(), (float) pose.z());
        Matrix4f view = new Matrix4f()
                .rotateX((float) Math.toRadians(-pose.pitch()))
                .rotateY((float) Math.toRadians(pose.yaw()))
                .translate(-eye.x, -eye.y, -eye.z);
        Matrix4f projection = new Matrix4f().perspective((float) Math.toRadians(pose.fov()), aspect, near, far);
        return new ViewCamera(view, projection, eye, near, far, NO_CLIP);
    }

    /** The same camera with a world-space clip plane (a, b, c, d): points with ax + by + cz + d &lt; 0 are cut. */
    public ViewCamera withClipPlane(Vector4fc plane) {
        return new ViewCamera(view, projection, position, near, far, plane);
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

    public Vector4fc clipPlane() {
        return clipPlane;
    }
}

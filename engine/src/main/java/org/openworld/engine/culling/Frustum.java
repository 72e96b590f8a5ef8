package org.openworld.engine.culling;

import org.joml.Matrix4f;
import org.joml.Matrix4fc;
import org.joml.Vector4f;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.culling.Visibility.Containment;

/**
 * The volume a camera sees, as world-space planes, and the paper's conservative box test against it (section 2.4).
 *
 * <p><b>Planes.</b> A world point {@code p} is drawn when its clip coordinates {@code c = VP · (p, 1)} satisfy
 * {@code −w ≤ x, y, z ≤ w}. Each of the six inequalities is linear in {@code p}: with {@code rᵢ} the rows of
 * {@code VP}, it reads {@code (r₃ ± rᵢ) · (p, 1) ≥ 0} (Gribb and Hartmann's extraction;
 * {@link Matrix4f#frustumPlane(int, Vector4f)} computes it). This is algebra on the matrix, so it holds for
 * perspective and orthographic projections, for oblique near planes, and for mirrored views
 * ({@code view · scale(1, −1, 1)}), whose handedness flips but whose clip inequalities do not. The planes are
 * scaled to unit normals, pointing inwards. The water's reflection camera has an oblique near plane that lies in the
 * water surface, so its frustum's near plane culls whatever is under the water.
 *
 * <p><b>Box test.</b> For a plane {@code (n, d)} and a box {@code [min, max]}, the corner furthest along {@code n}
 * is the positive vertex {@code p⁺ = (nₓ ≥ 0 ? maxₓ : minₓ, …)}, the nearest the negative vertex {@code p⁻}. Then
 * <ul>
 *   <li>{@code n · p⁺ + d < 0}: all eight corners are outside this plane, so the box is {@code OUTSIDE};</li>
 *   <li>{@code n · p⁻ + d ≥ 0} for every plane: all eight corners are inside every plane, so it is {@code INSIDE};</li>
 *   <li>otherwise {@code PARTIAL}.</li>
 * </ul>
 * This is conservative: a box near a frustum corner can be outside the frustum while no single plane has all its
 * corners outside, and is then kept as PARTIAL. It never rejects a box that the camera can see. Cost: two dot
 * products per plane, at most 12 per box.
 */
public final class Frustum {

    /** Left, right, bottom, top, near, far. */
    static final int PLANES = 6;
    /** The frustum planes in JOML's order: −x, +x, −y, +y, −z (near), +z (far). */
    private static final int[] JOML_PLANES = {
        Matrix4fc.PLANE_NX, Matrix4fc.PLANE_PX, Matrix4fc.PLANE_NY, Matrix4fc.PLANE_PY, Matrix4fc.PLANE_NZ,
        Matrix4fc.PLANE_PZ};

    /** a, b, c, d per plane: {@code a·x + b·y + c·z + d ≥ 0} inside, (a, b, c) a unit vector or zero. */
    private final float[] planes = new float[4 * PLANES];
    private final Vector4f plane = new Vector4f();

    /** A frustum that contains everything (every plane {@code (0, 0, 0, 1)}) until set. */
    public Frustum() {
        for (int i = 0; i < PLANES; i++) {
            planes[4 * i + 3] = 1;
        }
    }

    /** The planes of a pass camera's view-projection frustum. */
    public Frustum set(ViewCamera camera) {
        return set(camera.viewProjection());
    }

    /** @param viewProjection world → clip, OpenGL conventions (clip z from −w to w) */
    public Frustum set(Matrix4fc viewProjection) {
        for (int i = 0; i < PLANES; i++) {
            viewProjection.frustumPlane(JOML_PLANES[i], plane);
            store(i, plane);
        }
        return this;
    }

    /** Copies another frustum's planes (a frozen frustum keeps its copy). */
    public Frustum set(Frustum other) {
        System.arraycopy(other.planes, 0, planes, 0, planes.length);
        return this;
    }

    private void store(int index, Vector4f p) {
        float length = (float) Math.sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
        float scale = length > 0 ? 1 / length : 1;
        planes[4 * index] = p.x * scale;
        planes[4 * index + 1] = p.y * scale;
        planes[4 * index + 2] = p.z * scale;
        planes[4 * index + 3] = p.w * scale;
    }

    /**
     * Where one box of a {@link BoundsTree} lies, moved by a horizontal offset; allocates nothing.
     *
     * @param boxes   six floats per node: minX, minY, minZ, maxX, maxY, maxZ, metres
     * @param node    which box
     * @param offsetX added to the box's x, metres (the copy's offset)
     * @param offsetZ added to the box's z, metres
     */
    public Containment test(float[] boxes, int node, float offsetX, float offsetZ) {
        return test(boxes, node, offsetX, offsetZ, boxes[6 * node + 1], boxes[6 * node + 4]);
    }

    /** As {@link #test(float[], int, float, float)}, with the box's heights replaced by {@code minY .. maxY}. */
    public Containment test(float[] boxes, int node, float offsetX, float offsetZ, float minY, float maxY) {
        int b = 6 * node;
        float minX = boxes[b] + offsetX, minZ = boxes[b + 2] + offsetZ;
        float maxX = boxes[b + 3] + offsetX, maxZ = boxes[b + 5] + offsetZ;
        boolean inside = true;
        for (int i = 0; i < 4 * PLANES; i += 4) {
            float a = planes[i], bb = planes[i + 1], c = planes[i + 2], d = planes[i + 3];
            // the positive vertex, furthest along the inward normal: if it is outside, every corner is
            float positive = a * (a >= 0 ? maxX : minX) + bb * (bb >= 0 ? maxY : minY) + c * (c >= 0 ? maxZ : minZ) + d;
            if (positive < 0) {
                return Containment.OUTSIDE;
            }
            // the negative vertex, nearest: if it is outside, the plane cuts the box
            float negative = a * (a >= 0 ? minX : maxX) + bb * (bb >= 0 ? minY : maxY) + c * (c >= 0 ? minZ : maxZ) + d;
            inside &= negative >= 0;
        }
        return inside ? Containment.INSIDE : Containment.PARTIAL;
    }
}

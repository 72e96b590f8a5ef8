package org.openworld.engine.culling;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.joml.Matrix4d;
import org.joml.Matrix4f;
import org.joml.Vector3d;
import org.joml.Vector3f;
import org.joml.Vector4d;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;
import org.openworld.engine.water.MirrorCamera;
import org.openworld.engine.culling.Visibility.Containment;

/**
 * The box test against its ground truth, the clip inequalities {@code −w ≤ x, y, z ≤ w}, over random perspective,
 * orthographic, mirrored and oblique (the water's clipped reflection) cameras. Ground truth is computed in double precision from the same
 * matrix; a point within {@link #MARGIN} of a plane counts as on it, the width of float rounding in the planes.
 */
class FrustumTest {

    /** Deterministic: every run tests the same cameras and boxes. */
    private static final long SEED = 2017;
    private static final int CAMERAS = 300;
    private static final int BOXES_PER_CAMERA = 60;
    /** Grid of sample points per box edge (corners included): 9 × 9 × 9 points. */
    private static final int GRID = 9;
    /** Relative tolerance on a clip inequality, of |x| + |y| + |z| + |w|: far above float rounding (1e-7). */
    private static final double MARGIN = 1e-4;

    /** One random camera: its matrix for the frustum and, in double, for the ground truth. */
    private record Camera(Matrix4f viewProjection, Matrix4d exact, String kind) {
    }

    @Test
    void outsideBoxesHaveNoVisiblePointAndInsideBoxesNoHiddenCorner() {
        Random random = new Random(SEED);
        Map<Containment, Integer> seen = new EnumMap<>(Containment.class);
        Frustum frustum = new Frustum();
        float[] box = new float[6];
        for (int c = 0; c < CAMERAS; c++) {
            Camera camera = randomCamera(random, c);
            frustum.set(camera.viewProjection);
            for (int b = 0; b < BOXES_PER_CAMERA; b++) {
                randomBoxNearFrustum(random, camera, box);
                Containment containment = frustum.test(box, 0, 0, 0);
                seen.merge(containment, 1, Integer::sum);
                if (containment == Containment.OUTSIDE) {
                    requireNoSampleVisible(camera, box);
                } else if (containment == Containment.INSIDE) {
                    requireCornersVisible(camera, box);
                }
            }
        }
        // the box test's three cases must all occur, or the checks above proved nothing about them (KEPT is the
        // walk's, never a box test's)
        for (Containment containment : List.of(Containment.OUTSIDE, Containment.PARTIAL, Containment.INSIDE)) {
            assertTrue(seen.getOrDefault(containment, 0) > CAMERAS, containment + " seen too rarely: " + seen);
        }
    }

    @Test
    void boxesAroundAVisiblePointAreNeverOutside() {
        Random random = new Random(SEED + 1);
        Frustum frustum = new Frustum();
        float[] box = new float[6];
        for (int c = 0; c < CAMERAS; c++) {
            Camera camera = randomCamera(random, c);
            frustum.set(camera.viewProjection);
            for (int b = 0; b < BOXES_PER_CAMERA; b++) {
                Vector3d point = randomVisiblePoint(random, camera);
                double extent = scale(camera, point) * Math.pow(10, -3 + 3 * random.nextDouble());
                box[0] = (float) (point.x - extent * random.nextDouble());
                box[1] = (float) (point.y - extent * random.nextDouble());
                box[2] = (float) (point.z - extent * random.nextDouble());
                box[3] = (float) (point.x + extent * random.nextDouble());
                box[4] = (float) (point.y + extent * random.nextDouble());
                box[5] = (float) (point.z + extent * random.nextDouble());
                assertNotEquals(Containment.OUTSIDE, frustum.test(box, 0, 0, 0),
                        camera.kind + ": a box around the visible point " + point + " was culled");
            }
        }
    }

    @Test
    void outsideIsExactlyAllCornersOutsideOnePlane() {
        Random random = new Random(SEED + 2);
        Frustum frustum = new Frustum();
        float[] box = new float[6];
        int decided = 0;
        for (int c = 0; c < CAMERAS; c++) {
            Camera camera = randomCamera(random, c);
            frustum.set(camera.viewProjection);
            for (int b = 0; b < BOXES_PER_CAMERA; b++) {
                randomBoxNearFrustum(random, camera, box);
                Boolean oneRejectingPlane = allCornersOutsideOnePlane(camera, box);
                if (oneRejectingPlane != null) {
                    decided++;
                    assertEquals(oneRejectingPlane, frustum.test(box, 0, 0, 0) == Containment.OUTSIDE,
                            camera.kind + ": box " + java.util.Arrays.toString(box));
                }
            }
        }
        assertTrue(decided > CAMERAS * BOXES_PER_CAMERA * 9 / 10, "too many boxes within rounding of a plane");
    }

    @Test
    void offsetsMoveTheBox() {
        Frustum frustum = new Frustum().set(new Matrix4f().ortho(-10, 10, -10, 10, -10, 10));
        float[] box = {-1, -1, -1, 1, 1, 1};
        assertEquals(Containment.INSIDE, frustum.test(box, 0, 0, 0));
        assertEquals(Containment.PARTIAL, frustum.test(box, 0, 10, 0));
        assertEquals(Containment.OUTSIDE, frustum.test(box, 0, 0, -12));
    }

    /**
     * Perspective or orthographic, a random pose, sometimes mirrored in a horizontal plane, sometimes (perspective)
     * with an oblique near plane through the middle of the view.
     */
    private static Camera randomCamera(Random random, int index) {
        Vector3f eye = new Vector3f(sym(random, 100), sym(random, 100), sym(random, 100));
        Vector3f direction = new Vector3f(sym(random, 1), sym(random, 1), sym(random, 1)).normalize();
        Vector3f up = Math.abs(direction.y) > 0.95f ? new Vector3f(1, 0, 0) : new Vector3f(0, 1, 0);
        Matrix4f view = new Matrix4f().lookAt(eye, new Vector3f(eye).add(direction), up);
        boolean orthographic = index % 2 == 1;
        Matrix4f projection;
        if (orthographic) {
            float halfWidth = 5 + 200 * random.nextFloat();
            float halfHeight = halfWidth * (0.3f + random.nextFloat());
            float near = -100 + 110 * random.nextFloat();
            projection = new Matrix4f().ortho(-halfWidth, halfWidth, -halfHeight, halfHeight, near,
                    near + 10 + 500 * random.nextFloat());
        } else {
            float near = 0.1f + 10 * random.nextFloat();
            projection = new Matrix4f().perspective((float) Math.toRadians(20 + 100 * random.nextFloat()),
                    0.5f + 2.5f * random.nextFloat(), near, near * (10 + 1000 * random.nextFloat()));
        }
        String kind = orthographic ? "orthographic" : "perspective";
        if (index % 3 == 0) {
            // the water's camera: the world mirrored in the plane y = h, which flips handedness
            float h = sym(random, 50);
            view.translate(0, h, 0).scale(1, -1, 1).translate(0, -h, 0);
            kind += ", mirrored";
        }
        if (!orthographic && index % 5 == 0) {
            // a view-space plane of any direction through the middle of the view, the eye behind it
            Vector3f n = new Vector3f(sym(random, 1), sym(random, 1), sym(random, 1)).normalize();
            Vector3f middle = new Matrix4f(projection).invert().transformProject(new Vector3f(0, 0, 0));
            float d = -n.dot(middle);
            Vector4f plane = d < 0 ? new Vector4f(n, d) : new Vector4f(n.negate(), -d);
            projection = MirrorCamera.obliqueNearPlane(projection, plane);
            kind += ", oblique";
        }
        Matrix4f viewProjection = new Matrix4f(projection).mul(view);
        return new Camera(viewProjection, new Matrix4d(viewProjection), kind);
    }

    /** A box whose centre is near the frustum (its clip coordinates within ±1.5) and of a size from tiny to large. */
    private static void randomBoxNearFrustum(Random random, Camera camera, float[] box) {
        Vector3d centre = unproject(camera, sym(random, 1.5), sym(random, 1.5), -1 + 2.2 * random.nextDouble());
        double size = scale(camera, centre);
        for (int axis = 0; axis < 3; axis++) {
            double c = axis == 0 ? centre.x : axis == 1 ? centre.y : centre.z;
            double half = size * Math.pow(10, -3 + 3 * random.nextDouble());
            box[axis] = (float) (c - half);
            box[axis + 3] = (float) (c + half);
        }
    }

    /** A point strictly inside the frustum. */
    private static Vector3d randomVisiblePoint(Random random, Camera camera) {
        for (int attempt = 0; attempt < 1000; attempt++) {
            Vector3d p = unproject(camera, sym(random, 0.99), sym(random, 0.99), sym(random, 0.99));
            if (visible(camera, p.x, p.y, p.z, -MARGIN)) {
                return p;
            }
        }
        throw new IllegalStateException(camera.kind + ": nothing is visible");
    }

    /** Normalised device coordinates back to world space. */
    private static Vector3d unproject(Camera camera, double x, double y, double z) {
        return new Matrix4d(camera.exact).invert().transformProject(new Vector3d(x, y, z));
    }

    /** A length on the scale of the view near a point: its distance from the frustum's centre region. */
    private static double scale(Camera camera, Vector3d point) {
        Vector3d middle = unproject(camera, 0, 0, 0);
        return Math.max(1, point.distance(middle));
    }

    /**
     * Whether a point is drawn: {@code −w ≤ x, y, z ≤ w}, each with a slack of
     * {@code slack} times the size of the coordinates (positive: points just outside count as visible).
     */
    private static boolean visible(Camera camera, double x, double y, double z, double slack) {
        Vector4d c = camera.exact.transform(new Vector4d(x, y, z, 1));
        double tolerance = slack * (Math.abs(c.x) + Math.abs(c.y) + Math.abs(c.z) + Math.abs(c.w));
        return c.x >= -c.w - tolerance && c.x <= c.w + tolerance && c.y >= -c.w - tolerance && c.y <= c.w + tolerance
                && c.z >= -c.w - tolerance && c.z <= c.w + tolerance;
    }

    private static void requireNoSampleVisible(Camera camera, float[] box) {
        for (int i = 0; i < GRID; i++) {
            double x = box[0] + (box[3] - box[0]) * i / (GRID - 1.0);
            for (int j = 0; j < GRID; j++) {
                double y = box[1] + (box[4] - box[1]) * j / (GRID - 1.0);
                for (int k = 0; k < GRID; k++) {
                    double z = box[2] + (box[5] - box[2]) * k / (GRID - 1.0);
                    if (visible(camera, x, y, z, -MARGIN)) {
                        fail(camera.kind + ": box " + java.util.Arrays.toString(box) + " called OUTSIDE, but ("
                                + x + ", " + y + ", " + z + ") is visible");
                    }
                }
            }
        }
    }

    private static void requireCornersVisible(Camera camera, float[] box) {
        for (int corner = 0; corner < 8; corner++) {
            double x = box[(corner & 1) == 0 ? 0 : 3];
            double y = box[(corner & 2) == 0 ? 1 : 4];
            double z = box[(corner & 4) == 0 ? 2 : 5];
            assertTrue(visible(camera, x, y, z, MARGIN), camera.kind + ": box " + java.util.Arrays.toString(box)
                    + " called INSIDE, but its corner (" + x + ", " + y + ", " + z + ") is not visible");
        }
    }

    /**
     * Whether all eight corners are outside one of the six planes (the clip inequalities), in
     * double precision; null when a corner lies within the margin of a deciding plane, too close to call.
     */
    private static Boolean allCornersOutsideOnePlane(Camera camera, float[] box) {
        boolean undecided = false;
        for (int plane = 0; plane < 6; plane++) {
            boolean allOut = true;
            boolean anyNear = false;
            for (int corner = 0; corner < 8; corner++) {
                double x = box[(corner & 1) == 0 ? 0 : 3];
                double y = box[(corner & 2) == 0 ? 1 : 4];
                double z = box[(corner & 4) == 0 ? 2 : 5];
                double[] value = planeValue(camera, plane, x, y, z);
                allOut &= value[0] < -value[1];
                anyNear |= Math.abs(value[0]) <= value[1];
            }
            if (allOut) {
                return true;
            }
            undecided |= anyNear;
        }
        return undecided ? null : false;
    }

    /** A plane's value at a point (positive inside) and the margin around zero within which it is undecided. */
    private static double[] planeValue(Camera camera, int plane, double x, double y, double z) {
        Vector4d c = camera.exact.transform(new Vector4d(x, y, z, 1));
        double coordinate = plane / 2 == 0 ? c.x : plane / 2 == 1 ? c.y : c.z;
        double value = plane % 2 == 0 ? c.w + coordinate : c.w - coordinate;
        return new double[] {value, MARGIN * (Math.abs(c.x) + Math.abs(c.y) + Math.abs(c.z) + Math.abs(c.w))};
    }

    private static float sym(Random random, float half) {
        return (2 * random.nextFloat() - 1) * half;
    }

    private static double sym(Random random, double half) {
        return (2 * random.nextDouble() - 1) * half;
    }
}

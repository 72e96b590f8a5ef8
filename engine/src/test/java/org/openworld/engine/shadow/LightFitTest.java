package org.openworld.engine.shadow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import java.util.function.Function;
import org.joml.Matrix3d;
import org.joml.Matrix4d;
import org.joml.Matrix4f;
import org.joml.Matrix4fc;
import org.joml.Vector3d;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.ViewCamera;

/**
 * Both light fits against ground truth computed here in double precision from the camera's pose (not from the code
 * under test): the slice's corners, the clip cube, the texel grid. Cameras, slices and suns are random but seeded.
 */
class LightFitTest {
    // Tolerances here: float sun directions and matrices (24-bit mantissa, 6e-8) make rotations orthonormal to 1e-6 and
    // rigid to 1e-5; the clip cube's slack is CLIP_SLACK below; radii in double to 1e-6 to 1e-4

    /** Deterministic: every run tests the same cameras, slices and suns. */
    private static final long SEED = 2017;
    /** Shadow-map texels per side, the engine's usual size. */
    private static final int RESOLUTION = 2048;
    /** Slack on the clip cube, clip units: float matrices round at about 1e-7 of the box. */
    private static final double CLIP_SLACK = 1e-4;
    /** How far from a whole number of texels a snapped shift may be, texels: float rounding of the matrices. */
    private static final double TEXEL_SLACK = 1e-3;
    /**
     * How far from whole texels a snapped depth may be, as a fraction of the box's distance from the world's origin
     * (four float epsilons, 4 · 2⁻²³): the projection's depth offset is a float of that size. At 2 km that is 1 mm,
     * at 100 m 0.05 mm, far below any depth bias.
     */
    private static final double DEPTH_ROUNDING = 4 * Math.ulp(1f);
    /** Near and far planes of the random cameras' projections, metres (the slices lie anywhere, not only inside). */
    private static final float CAMERA_NEAR = 0.5f;
    private static final float CAMERA_FAR = 1200;

    /** A random camera with the pose it was made from, and one slice of it. */
    private record Scene(ViewCamera camera, CameraPose pose, double aspect, double from, double to) {
    }

    private static Scene randomScene(Random random, double positionRange) {
        CameraPose pose = new CameraPose(
                positionRange * (2 * random.nextDouble() - 1), positionRange * random.nextDouble(),
                positionRange * (2 * random.nextDouble() - 1), 360 * random.nextDouble(),
                -89 + 178 * random.nextDouble(), 40 + 50 * random.nextDouble());
        double aspect = 1 + 1.4 * random.nextDouble();
        double from = CAMERA_NEAR + 300 * Math.pow(random.nextDouble(), 3);
        double to = from * (1.5 + 30 * random.nextDouble());
        return new Scene(ViewCamera.perspective(pose, (float) aspect, CAMERA_NEAR, CAMERA_FAR), pose, aspect, from, to);
    }

    /** A unit vector towards a sun at a random azimuth and an elevation from 3° to 89°. */
    private static Vector3f randomSun(Random random) {
        double elevation = Math.toRadians(3 + 86 * random.nextDouble());
        double azimuth = 2 * Math.PI * random.nextDouble();
        return new Vector3f((float) (Math.cos(elevation) * Math.sin(azimuth)), (float) Math.sin(elevation),
                (float) (-Math.cos(elevation) * Math.cos(azimuth))).normalize();
    }

    /**
     * The slice's 8 world corners from the pose's field of view and aspect, {@code (±d·a·t, ±d·t, −d)} with
     * {@code t = tan(fov/2)}, taken to the world in double through the camera's own (float) view matrix: the slice of
     * the camera the fit was given, not of a nearby one a float matrix cannot hold.
     */
    private static Vector3d[] exactCorners(Scene scene) {
        Matrix4d toWorld = new Matrix4d(scene.camera.view()).invertAffine();
        double tanY = Math.tan(Math.toRadians(scene.pose.fov()) / 2);
        double tanX = tanY * scene.aspect;
        Vector3d[] corners = new Vector3d[8];
        for (int i = 0; i < 8; i++) {
            double d = i < 4 ? scene.from : scene.to;
            corners[i] = toWorld.transformPosition(new Vector3d(
                    ((i & 1) == 0 ? -1 : 1) * d * tanX, ((i & 2) == 0 ? -1 : 1) * d * tanY, -d));
        }
        return corners;
    }

    private static Vector3d clip(LightBox box, Vector3d world) {
        return new Matrix4d(box.viewProjection()).transformProject(new Vector3d(world));
    }

    /**
     * The fit works in float on world positions: a few ulps of the point's largest coordinate, in clip units of the
     * box's half-width. Negligible for a box hundreds of metres wide; a slice a metre deep 2 km from the origin has a
     * box of about a metre, where 4 ulps of 2 km (0.5 mm) are 5e-4 of it.
     */
    private static double rounding(LightBox box, Vector3d point) {
        return 4 * Math.ulp((float) maxAbs(point)) / (box.texelSize() * RESOLUTION / 2);
    }

    private static double maxAbs(Vector3d v) {
        return Math.max(Math.abs(v.x), Math.max(Math.abs(v.y), Math.abs(v.z)));
    }

    @Test
    void bothFitsHoldEverySliceCornerAndTheCastersTowardsTheSun() {
        Random random = new Random(SEED);
        double worstStable = 0;
        double worstCovering = 0;
        for (int trial = 0; trial < 2000; trial++) {
            Scene scene = randomScene(random, 1000);
            Vector3f toSun = randomSun(random);
            double reach = random.nextInt(4) == 0 ? 0 : 2000 * random.nextDouble();
            LightBox stable = LightFit.stable(scene.camera.view(), scene.camera.projection(), scene.from, scene.to,
                    toSun, reach, RESOLUTION);
            LightBox covering = LightFit.covering(scene.camera.view(), scene.camera.projection(), scene.from,
                    scene.to, toSun, reach, RESOLUTION);
            Vector3d shift = new Vector3d(toSun.x, toSun.y, toSun.z).mul(reach);
            for (Vector3d corner : exactCorners(scene)) {
                Vector3d caster = new Vector3d(corner).add(shift);
                for (Vector3d point : new Vector3d[] {corner, caster}) {
                    double s = maxAbs(clip(stable, point));
                    double c = maxAbs(clip(covering, point));
                    String label = "trial " + trial + ", point " + point + ", " + scene;
                    assertTrue(s <= 1 + CLIP_SLACK + rounding(stable, point), "stable fit misses it by " + (s - 1)
                            + ": " + label);
                    assertTrue(c <= 1 + CLIP_SLACK + rounding(covering, point), "covering fit misses it by "
                            + (c - 1) + ": " + label);
                    worstStable = Math.max(worstStable, s);
                    worstCovering = Math.max(worstCovering, c - rounding(covering, point));
                }
            }
        }
        // The covering box is tight: some corner or caster lies on its boundary.
        assertEquals(1, worstCovering, CLIP_SLACK);
        // the stable box is a sphere's bounding box: some corner must reach 90 % of its half-width, or the box is
        // needlessly loose (the sphere costs at most √3 over a tight cube)
        assertTrue(worstStable > 0.9, "the stable box is not much larger than needed: " + worstStable);
    }

    @Test
    void sliceCornersMatchThePoseGroundTruth() {
        Random random = new Random(SEED + 1);
        for (int trial = 0; trial < 200; trial++) {
            Scene scene = randomScene(random, 1000);
            Vector3d[] exact = exactCorners(scene);
            Vector3d[] corners = LightFit.sliceCorners(scene.camera.view(), scene.camera.projection(), scene.from,
                    scene.to);
            for (int i = 0; i < 8; i++) {
                double tolerance = 1e-6 * scene.to;
                assertTrue(exact[i].distance(corners[i]) <= tolerance, "corner " + i + ": " + corners[i]
                        + " vs " + exact[i]);
            }
        }
    }

    @Test
    void sliceRadiusHoldsEveryCornerAndIsTheSmallestSuchSphere() {
        Random random = new Random(SEED + 2);
        for (int trial = 0; trial < 1000; trial++) {
            Scene scene = randomScene(random, 0);
            double tanY = Math.tan(Math.toRadians(scene.pose.fov()) / 2);
            double k = Math.hypot(tanY, tanY * scene.aspect);
            double r = LightFit.sliceRadius(scene.camera.projection(), scene.from, scene.to);
            String label = "trial " + trial + ", " + scene + ", r = " + r;
            assertTrue(fitsOnAxis(k, scene.from, scene.to, r * (1 + 1e-6)), "corners outside: " + label);
            assertTrue(!fitsOnAxis(k, scene.from, scene.to, r * (1 - 1e-5)), "a smaller sphere fits: " + label);
        }
    }

    /**
     * Whether a sphere of radius {@code r} centred somewhere on the view axis holds every corner of the slice: the near
     * corners ({@code k·n} off the axis) need a centre within {@code sqrt(r² − k²n²)} of {@code n}, the far ones within
     * {@code sqrt(r² − k²f²)} of {@code f}, and the two intervals must meet. (By symmetry the smallest sphere's centre is
     * on the axis.)
     */
    private static boolean fitsOnAxis(double k, double n, double f, double r) {
        double nearRoom = r * r - k * k * n * n;
        double farRoom = r * r - k * k * f * f;
        return farRoom >= 0 && nearRoom >= 0 && n + Math.sqrt(nearRoom) >= f - Math.sqrt(farRoom);
    }

    @Test
    void sliceRadiusOfHandWorkedFrusta() {
        // 90° square frustum: P00 = P11 = 1, k = sqrt(2); z* = 3·(1 + 3)/2 = 6 > 3, so the far square sets it: 3·sqrt(2).
        Matrix4f square90 = new Matrix4f().perspective((float) Math.toRadians(90), 1, 0.1f, 100);
        // doubles: 1e-6 and 1e-4 on radii of a few to tens of metres, far above round-off (the 1e-4 on √1275 ≈ 35.7)
        assertEquals(3 * Math.sqrt(2), LightFit.sliceRadius(square90, 1, 3), 1e-6);
        // P00 = P11 = 2 (tan 26.57° = 0.5), k² = 0.5; 10..50 m: z* = 1.5·60/2 = 45 < 50, r = sqrt(35² + 0.5·10²).
        Matrix4f narrow = new Matrix4f().perspective((float) (2 * Math.atan(0.5)), 1, 0.1f, 100);
        assertEquals(Math.sqrt(1275), LightFit.sliceRadius(narrow, 10, 50), 1e-4);
        // The far corners are also sqrt(1275) from z* = 45: (50 − 45)² + 0.5·50² = 1275.
    }

    @Test
    void stableBoxSizeDependsOnlyOnTheSliceAndFieldOfView() {
        Random random = new Random(SEED + 3);
        int coveringChanged = 0;
        for (int trial = 0; trial < 100; trial++) {
            Scene a = randomScene(random, 1000);
            CameraPose other = new CameraPose(-a.pose.z(), a.pose.y() + 300, a.pose.x(), a.pose.yaw() + 137,
                    -a.pose.pitch() / 2, a.pose.fov());
            ViewCamera b = ViewCamera.perspective(other, (float) a.aspect, CAMERA_NEAR, CAMERA_FAR);
            assertEquals(LightFit.sliceRadius(a.camera.projection(), a.from, a.to),
                    LightFit.sliceRadius(b.projection(), a.from, a.to));
            Vector3f toSun = randomSun(random);
            LightBox boxA = LightFit.stable(a.camera.view(), a.camera.projection(), a.from, a.to, toSun, 100,
                    RESOLUTION);
            LightBox boxB = LightFit.stable(b.view(), b.projection(), a.from, a.to, randomSun(random), 100,
                    RESOLUTION);
            Matrix4fc pa = boxA.projection();
            Matrix4fc pb = boxB.projection();
            assertEquals(pa.m00(), pb.m00(), "width, trial " + trial);
            assertEquals(pa.m11(), pb.m11(), "height, trial " + trial);
            assertEquals(pa.m22(), pb.m22(), "depth, trial " + trial);
            assertEquals(boxA.texelSize(), boxB.texelSize(), "trial " + trial);
            assertEquals(boxA.depthRange(), boxB.depthRange(), "trial " + trial);
            LightBox coveringA = LightFit.covering(a.camera.view(), a.camera.projection(), a.from, a.to, toSun, 100,
                    RESOLUTION);
            LightBox coveringB = LightFit.covering(b.view(), b.projection(), a.from, a.to, toSun, 100, RESOLUTION);
            if (coveringA.texelSize() != coveringB.texelSize()) {
                coveringChanged++;
            }
        }
        // a random turn changes the tight box's size almost always: 90 of 100 allows for turns that happen to keep it
        assertTrue(coveringChanged > 90, "the covering box changes size as the camera turns, in "
                + coveringChanged + " of 100 trials");
    }

    @Test
    void stableGridStaysFixedInTheWorldAsTheCameraMovesAndTurns() {
        Random random = new Random(SEED + 4);
        for (int trial = 0; trial < 300; trial++) {
            Scene scene = randomScene(random, 2000);
            Vector3f toSun = randomSun(random);
            LightBox before = LightFit.stable(scene.camera.view(), scene.camera.projection(), scene.from, scene.to,
                    toSun, 50, RESOLUTION);
            // Moves of a few texels, and of less than one; every third also turns.
            double step = before.texelSize() * (trial % 2 == 0 ? 5 : 0.7);
            boolean turn = trial % 3 == 0;
            CameraPose moved = new CameraPose(scene.pose.x() + step * (2 * random.nextDouble() - 1),
                    scene.pose.y() + step * (2 * random.nextDouble() - 1),
                    scene.pose.z() + step * (2 * random.nextDouble() - 1),
                    scene.pose.yaw() + (turn ? 20 * random.nextDouble() : 0),
                    scene.pose.pitch() * (turn ? random.nextDouble() : 1), scene.pose.fov());
            ViewCamera camera = ViewCamera.perspective(moved, (float) scene.aspect, CAMERA_NEAR, CAMERA_FAR);
            LightBox after = LightFit.stable(camera.view(), camera.projection(), scene.from, scene.to, toSun, 50,
                    RESOLUTION);
            double depthSlack = DEPTH_ROUNDING * before.sunwardCentre().length() / before.texelSize();
            for (Vector3d point : exactCorners(scene)) {
                Vector3d shift = texels(after, point).sub(texels(before, point));
                String label = "trial " + trial + ", shift " + shift + " texels";
                assertTrue(fraction(shift.x) <= TEXEL_SLACK, "x: " + label);
                assertTrue(fraction(shift.y) <= TEXEL_SLACK, "y: " + label);
                assertTrue(fraction(shift.z) <= depthSlack, "depth: " + label);
            }
        }
    }

    @Test
    void coveringGridSlidesWithTheCamera() {
        Random random = new Random(SEED + 5);
        int fractional = 0;
        int moves = 100;
        for (int trial = 0; trial < moves; trial++) {
            Scene scene = randomScene(random, 100);
            Vector3f toSun = randomSun(random);
            LightBox before = LightFit.covering(scene.camera.view(), scene.camera.projection(), scene.from, scene.to,
                    toSun, 50, RESOLUTION);
            double step = before.texelSize() * 5;
            CameraPose moved = new CameraPose(scene.pose.x() + step * (2 * random.nextDouble() - 1), scene.pose.y(),
                    scene.pose.z() + step * (2 * random.nextDouble() - 1), scene.pose.yaw(), scene.pose.pitch(),
                    scene.pose.fov());
            ViewCamera camera = ViewCamera.perspective(moved, (float) scene.aspect, CAMERA_NEAR, CAMERA_FAR);
            LightBox after = LightFit.covering(camera.view(), camera.projection(), scene.from, scene.to, toSun, 50,
                    RESOLUTION);
            Vector3d shift = texels(after, new Vector3d(0, 0, 0)).sub(texels(before, new Vector3d(0, 0, 0)));
            if (fraction(shift.x) > 0.01 || fraction(shift.y) > 0.01) {
                fractional++;
            }
        }
        assertTrue(fractional > moves / 2, "only " + fractional + " of " + moves + " moves shift the grid by part of a"
                + " texel: the covering fit should swim");
    }

    /** A world point in shadow-map texels: clip x, y times resolution / 2, and its depth in texel-sized steps. */
    private static Vector3d texels(LightBox box, Vector3d world) {
        Vector3d c = clip(box, world);
        return new Vector3d(c.x * RESOLUTION / 2, c.y * RESOLUTION / 2, c.z * box.depthRange() / 2 / box.texelSize());
    }

    /** Distance to the nearest whole number. */
    private static double fraction(double value) {
        return Math.abs(value - Math.rint(value));
    }

    @Test
    void lightRotationIsARotationTakingTheSunToPlusZ() {
        Random random = new Random(SEED + 6);
        Vector3f[] suns = new Vector3f[203];
        suns[0] = new Vector3f(0, 1, 0);
        suns[1] = new Vector3f(0, -1, 0);
        suns[2] = new Vector3f(0.01f, 1, 0.02f).normalize();
        for (int i = 3; i < suns.length; i++) {
            suns[i] = new Vector3f((float) random.nextGaussian(), (float) random.nextGaussian(),
                    (float) random.nextGaussian()).normalize();
        }
        for (Vector3f toSun : suns) {
            Matrix4f rotation = LightFit.lightRotation(toSun);
            Matrix3d m = new Matrix4d(rotation).get3x3(new Matrix3d());
            Matrix3d product = new Matrix3d(m).mul(new Matrix3d(m).transpose());
            for (int col = 0; col < 3; col++) {
                for (int row = 0; row < 3; row++) {
                    // float vectors in, double matrices out: 1e-6 covers the float sun direction's rounding (24-bit
                    // mantissa, 6e-8)
                    assertEquals(col == row ? 1 : 0, product.get(col, row), 1e-6, "R·Rᵀ for " + toSun);
                }
            }
            assertEquals(1, m.determinant(), 1e-6, "det for " + toSun);
            assertEquals(0, rotation.m30(), 0);
            assertEquals(0, rotation.m31(), 0);
            assertEquals(0, rotation.m32(), 0);
            Vector3f light = rotation.transformDirection(new Vector3f(toSun));
            assertEquals(0, light.x, 1e-6, "x of the sun in light space, " + toSun);
            assertEquals(0, light.y, 1e-6, "y of the sun in light space, " + toSun);
            assertEquals(1, light.z, 1e-6, "z of the sun in light space, " + toSun);
            // Light +Y is the world's up seen from the sun; near the zenith it is north (world −Z).
            Vector3f up = rotation.positiveY(new Vector3f());
            if (Math.abs(toSun.y) < Math.cos(Math.toRadians(8))) {
                assertTrue(up.y > 0, "light up " + up + " for " + toSun);
            } else {
                assertTrue(up.z < 0, "light up " + up + " for " + toSun);
            }
        }
    }

    @Test
    void texelSizeAndDepthRangeMatchTheBox() {
        Random random = new Random(SEED + 7);
        for (int trial = 0; trial < 200; trial++) {
            Scene scene = randomScene(random, 1000);
            Vector3f toSun = randomSun(random);
            double reach = 1000 * random.nextDouble();
            int resolution = 256 << random.nextInt(5);
            for (Function<Scene, LightBox> fit : List.<Function<Scene, LightBox>>of(
                    s -> LightFit.stable(s.camera.view(), s.camera.projection(), s.from, s.to, toSun, reach,
                            resolution),
                    s -> LightFit.covering(s.camera.view(), s.camera.projection(), s.from, s.to, toSun, reach,
                            resolution))) {
                LightBox box = fit.apply(scene);
                Matrix4d inverse = new Matrix4d(box.viewProjection()).invert();
                Vector3d centre = inverse.transformProject(new Vector3d(0, 0, 0));
                Vector3d right = inverse.transformProject(new Vector3d(1, 0, 0)).sub(centre);
                Vector3d top = inverse.transformProject(new Vector3d(0, 1, 0)).sub(centre);
                Vector3d near = inverse.transformProject(new Vector3d(0, 0, -1));
                Vector3d far = inverse.transformProject(new Vector3d(0, 0, 1));
                double width = 2 * Math.max(right.length(), top.length());
                double tolerance = 1e-5 * (1 + scene.to + reach);
                assertEquals(width, box.texelSize() * (double) resolution, tolerance, "trial " + trial);
                assertEquals(near.distance(far), box.depthRange(), tolerance, "trial " + trial);
                Vector3d sunward = new Vector3d(near).sub(far).normalize();
                // float inputs (24-bit mantissa): 1e-5 on unit-length quantities
                assertEquals(1, sunward.dot(toSun.x, toSun.y, toSun.z), 1e-5, "near face towards the sun");
                Vector3f eye = box.sunwardCentre();
                assertTrue(near.distance(eye.x, eye.y, eye.z) <= tolerance, "sunward centre " + eye + " vs " + near);
                assertEquals(1, new Matrix4d(box.view()).determinant3x3(), 1e-5, "view is a rigid motion");
            }
        }
    }

    @Test
    void lightBoxKeepsItsOwnCopies() {
        Matrix4f view = new Matrix4f().translation(1, 2, 3);
        Matrix4f projection = new Matrix4f().setOrtho(-1, 1, -1, 1, 0, 10);
        LightBox box = new LightBox(view, projection, 0.5f, 10);
        view.identity();
        projection.identity();
        ((Matrix4f) box.view()).identity();
        ((Matrix4f) box.projection()).identity();
        assertEquals(new Matrix4f().translation(1, 2, 3), box.view());
        assertEquals(new Matrix4f().setOrtho(-1, 1, -1, 1, 0, 10), box.projection());
        box.viewProjection().identity();
        assertEquals(new Matrix4f().setOrtho(-1, 1, -1, 1, 0, 10).translate(1, 2, 3), box.viewProjection());
        assertMessage("texelSize", () -> new LightBox(view, projection, 0, 10));
        assertMessage("depthRange", () -> new LightBox(view, projection, 1, -1));
    }

    @Test
    void badInputsAreRejectedByName() {
        Matrix4fc v = new Matrix4f();
        Matrix4fc p = new Matrix4f().perspective(1, 1.5f, 0.5f, 1000);
        Vector3f sun = new Vector3f(0, 1, 1).normalize();
        assertMessage("from", () -> LightFit.stable(v, p, 0, 10, sun, 0, 1024));
        assertMessage("to", () -> LightFit.covering(v, p, 10, 10, sun, 0, 1024));
        assertMessage("to", () -> LightFit.sliceRadius(p, 10, 5));
        assertMessage("resolution", () -> LightFit.stable(v, p, 1, 10, sun, 0, 1));
        assertMessage("resolution", () -> LightFit.covering(v, p, 1, 10, sun, 0, 0));
        assertMessage("reach", () -> LightFit.stable(v, p, 1, 10, sun, -1, 1024));
        assertMessage("reach", () -> LightFit.covering(v, p, 1, 10, sun, Double.NaN, 1024));
        assertMessage("toSun", () -> LightFit.stable(v, p, 1, 10, new Vector3f(0, 2, 0), 0, 1024));
        assertMessage("toSun", () -> LightFit.lightRotation(new Vector3f()));
        assertMessage("projection", () -> LightFit.sliceRadius(new Matrix4f().zero(), 1, 10));
    }

    private static void assertMessage(String expected, Runnable call) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, call::run);
        assertTrue(e.getMessage().contains(expected), "message '" + e.getMessage() + "' names " + expected);
    }
}

package org.openworld.engine.water;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.ViewCamera;

/** The mirror matrix and the oblique clip plane against hand-worked cases. */
class MirrorCameraTest {
    // Tolerances here: float matrices (24-bit mantissa, ~6e-8 relative): 1e-6 on NDC and unit quantities, 1e-5 on
    // coordinates of a few metres, 1e-3 on NDC depth over 20-45 m

    private static final float LEVEL = 2;
    private static final ViewCamera VIEWER = ViewCamera.perspective(new CameraPose(0, 10, 0, 0, -30, 60), 16f / 9,
            0.5f, 40_000);

    @Test
    void theMirrorFlipsHeightsAboutTheLevel() {
        Matrix4f m = MirrorCamera.reflection(LEVEL);
        assertEquals(new Vector3f(1, -1, 3), m.transformPosition(new Vector3f(1, 5, 3)));
        assertEquals(new Vector3f(-4, 2, 7), m.transformPosition(new Vector3f(-4, 2, 7)));
        // float matrices (24-bit mantissa, ~6e-8 relative): 1e-6 on unit quantities, 1e-5 on coordinates of a few
        // metres
        assertEquals(-1, m.determinant(), 1e-6);
    }

    @Test
    void theMirroredCameraSeesEachPointWhereTheViewerSeesItsMirrorImage() {
        ViewCamera mirror = MirrorCamera.of(VIEWER, LEVEL, false);
        assertEquals(new Vector3f(0, -6, 0), mirror.position());
        assertTrue(mirror.mirrored());
        assertFalse(VIEWER.mirrored());
        Vector3f p = new Vector3f(5, 7, -30);
        Vector4f seenInMirror = ndc(mirror, p);
        Vector4f seenDirectly = ndc(VIEWER, new Vector3f(5, 2 * LEVEL - 7, -30));
        assertEquals(seenDirectly.x, seenInMirror.x, 1e-5);
        assertEquals(seenDirectly.y, seenInMirror.y, 1e-5);
    }

    @Test
    void anObliqueNearPlaneParallelToTheOldOneIsJustANearerPlane() {
        // Looking down −Z with near 1 and far 100; the plane z = −5 (kept side further away): C = (0, 0, −1, −5).
        Matrix4f projection = new Matrix4f().perspective((float) Math.toRadians(90), 1, 1, 100);
        Matrix4f oblique = MirrorCamera.obliqueNearPlane(projection, new Vector4f(0, 0, -1, -5));
        assertEquals(-1, ndcZ(oblique, new Vector3f(0, 0, -5)), 1e-5);
        assertEquals(-1, ndcZ(oblique, new Vector3f(3, -2, -5)), 1e-5);
        // q, the far corner opposite the plane, stays on the far plane
        assertEquals(1, ndcZ(oblique, new Vector3f(0, 0, -100)), 1e-4);
        // the x and y rows are untouched, so the picture is the same
        Vector4f a = oblique.transform(new Vector4f(3, -2, -50, 1));
        Vector4f b = projection.transform(new Vector4f(3, -2, -50, 1));
        assertEquals(b.x / b.w, a.x / a.w, 1e-6);
        assertEquals(b.y / b.w, a.y / a.w, 1e-6);
    }

    @Test
    void theClippedMirrorCutsExactlyAtTheWater() {
        ViewCamera mirror = MirrorCamera.of(VIEWER, LEVEL, true);
        // 1e-3 of NDC: the oblique near plane lies on the water to float rounding of a projection over 20–45 m
        assertEquals(-1, ndc(mirror, new Vector3f(3, LEVEL, -20)).z, 1e-3);
        assertEquals(-1, ndc(mirror, new Vector3f(-8, LEVEL, -45)).z, 1e-3);
        assertTrue(ndc(mirror, new Vector3f(3, LEVEL + 0.5f, -20)).z > -1, "above the water is kept");
        assertTrue(ndc(mirror, new Vector3f(3, LEVEL - 0.5f, -20)).z < -1, "below the water is clipped");
        // and the same picture as the unclipped mirror
        Vector4f clipped = ndc(mirror, new Vector3f(5, 7, -30));
        Vector4f unclipped = ndc(MirrorCamera.of(VIEWER, LEVEL, false), new Vector3f(5, 7, -30));
        assertEquals(unclipped.x, clipped.x, 1e-5);
        assertEquals(unclipped.y, clipped.y, 1e-5);
    }

    @Test
    void aPlaneInFrontOfTheEyeIsRefused() {
        Matrix4f projection = new Matrix4f().perspective(1, 1, 1, 100);
        assertThrows(IllegalArgumentException.class,
                () -> MirrorCamera.obliqueNearPlane(projection, new Vector4f(0, 0, 1, 5)));
    }

    private static Vector4f ndc(ViewCamera camera, Vector3f p) {
        Vector4f c = new Matrix4f(camera.viewProjection()).transform(new Vector4f(p, 1));
        return c.div(c.w);
    }

    private static float ndcZ(Matrix4f projection, Vector3f p) {
        Vector4f c = projection.transform(new Vector4f(p, 1));
        return c.z / c.w;
    }
}

package org.openworld.engine.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.joml.Matrix4f;
import org.joml.Vector3d;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.openworld.engine.core.ViewCamera;

class CameraMathTest {

    private static final double EPS = 1e-12;

    private static void assertVector(double x, double y, double z, Vector3d v) {
        assertEquals(x, v.x, EPS, "x of " + v);
        assertEquals(y, v.y, EPS, "y of " + v);
        assertEquals(z, v.z, EPS, "z of " + v);
    }

    @Test
    void forwardPointsToTheCompassDirectionOfTheYaw() {
        assertVector(0, 0, -1, CameraMath.forward(0, 0));    // north is −Z
        assertVector(1, 0, 0, CameraMath.forward(90, 0));    // east is +X
        assertVector(0, 0, 1, CameraMath.forward(180, 0));   // south is +Z
        assertVector(-1, 0, 0, CameraMath.forward(270, 0));  // west is −X
    }

    @Test
    void pitchTiltsForwardUpAndKeepsItOfUnitLength() {
        assertVector(0, 1, 0, CameraMath.forward(0, 90));
        double h = Math.sqrt(0.5);
        assertVector(h, h, 0, CameraMath.forward(90, 45));
        assertVector(0, -h, -h, CameraMath.forward(0, -45));
        assertEquals(1, CameraMath.forward(123, -37).length(), EPS);
    }

    @Test
    void rightIsForwardCrossUpAndHorizontal() {
        for (double yaw = 0; yaw < 360; yaw += 30) {
            Vector3d expected = CameraMath.forward(yaw, 20).cross(0, 1, 0).normalize();
            Vector3d right = CameraMath.right(yaw);
            assertVector(expected.x, expected.y, expected.z, right);
        }
        assertVector(1, 0, 0, CameraMath.right(0));   // facing north, east is on the right
        assertVector(0, 0, 1, CameraMath.right(90));  // facing east, south is on the right
    }

    @Test
    void forwardMatchesTheViewMatrixOfViewCamera() {
        CameraPose pose = new CameraPose(0, 0, 0, 130, 25, 60);
        Vector3d f = CameraMath.forward(pose.yaw(), pose.pitch());
        Matrix4f view = new Matrix4f(ViewCamera.perspective(pose, 1, 0.5f, 100).view());
        Vector3f inView = view.transformDirection(new Vector3f((float) f.x, (float) f.y, (float) f.z));
        // float matrices (24-bit mantissa): 1e-6 on unit vectors; the angles in double to 1e-9
        assertEquals(0, inView.x, 1e-6);
        assertEquals(0, inView.y, 1e-6);
        assertEquals(-1, inView.z, 1e-6);
    }

    @Test
    void yawAndPitchOfADirectionInvertForward() {
        Vector3d f = CameraMath.forward(250, -30);
        assertEquals(250, CameraMath.yawOf(f.x, f.z), 1e-9);
        assertEquals(-30, CameraMath.pitchOf(f.x, f.y, f.z), 1e-9);
    }

    @Test
    void anglesNormaliseAndClamp() {
        assertEquals(350, CameraMath.normalizeYaw(-10), EPS);
        assertEquals(10, CameraMath.normalizeYaw(730), EPS);
        assertEquals(0, CameraMath.normalizeYaw(360), EPS);
        assertEquals(0, CameraMath.normalizeYaw(-1e-15), EPS);
        assertEquals(20, CameraMath.yawDifference(350, 10), EPS);
        assertEquals(-20, CameraMath.yawDifference(10, 350), EPS);
        assertEquals(89, CameraMath.clampPitch(120), EPS);
        assertEquals(-89, CameraMath.clampPitch(-95), EPS);
    }
}

package org.openworld.engine.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_LEFT;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_UP;

import org.junit.jupiter.api.Test;

/** Mouse and arrow-key look: smoothing, clamping, wrapping. */
class CameraLookTest {
    // Tolerances here: angles in double: sums of mouse steps times the sensitivity to 1e-9 to 1e-6; 1e-3° where an
    // exponential smoothing must have converged

    private static final double SENSITIVITY = CameraSettings.DEFAULTS.mouseSensitivity();

    @Test
    void mouseSmoothingConvergesToTheAim() {
        CameraRig rig = new CameraRig().at(0, 100, 0, 0, 0);
        rig.input.setLooking(true);
        rig.run(1.0 / 60);
        rig.input.mouseMoved(250, -100);   // right and up
        rig.run(1.0 / 60);
        double aimYaw = 250 * SENSITIVITY;
        double aimPitch = 100 * SENSITIVITY;
        // one 1/60 s step of the exponential smoothing covers well under half the way; after 30 more steps what is left
        // of the gap is under 1e-3°
        assertTrue(rig.pose().yaw() > 0 && rig.pose().yaw() < 0.5 * aimYaw, "smoothed, not at once: " + rig.pose());
        double previousGap = aimYaw - rig.pose().yaw();
        for (int i = 0; i < 30; i++) {
            rig.run(1.0 / 60);
            double gap = aimYaw - rig.pose().yaw();
            assertTrue(gap >= 0 && gap < previousGap, "approaches without overshoot");
            previousGap = gap;
        }
        assertEquals(aimYaw, rig.pose().yaw(), 1e-3);
        assertEquals(aimPitch, rig.pose().pitch(), 1e-3);
        assertEquals(0, rig.pose().x(), 0, "looking does not move");
    }

    @Test
    void withoutSmoothingTheViewTurnsAtOnce() {
        CameraRig rig = new CameraRig().at(0, 100, 0, 0, 0).set("camera.look-smoothing", "0");
        rig.input.setLooking(true);
        rig.input.mouseMoved(100, 0);
        rig.run(1.0 / 60);
        assertEquals(100 * SENSITIVITY, rig.pose().yaw(), 1e-9);
    }

    @Test
    void theMouseTurnsOnlyWhileLooking() {
        CameraRig rig = new CameraRig().at(0, 100, 0, 0, 0);
        rig.input.mouseMoved(300, 300);
        rig.run(1);
        assertEquals(0, rig.pose().yaw(), 0);
        rig.input.setLooking(true);
        rig.run(1);
        assertEquals(0, rig.pose().yaw(), 0, "movement from before looking is dropped, not saved up");
    }

    @Test
    void pitchClampsAt89Degrees() {
        CameraRig rig = new CameraRig().at(0, 100, 0, 0, 0);
        rig.input.setLooking(true);
        rig.input.mouseMoved(0, -10_000);   // far up
        rig.run(2);
        // doubles: sums of whole-degree inputs times the sensitivity, equal to round-off (1e-6 to 1e-9); 1e-3° where a
        // smoothing must have converged
        assertEquals(89, rig.pose().pitch(), 1e-6);
        rig.input.mouseMoved(0, 30_000);    // far down
        rig.run(2);
        assertEquals(-89, rig.pose().pitch(), 1e-6);
        rig.input.mouseMoved(0, -100);      // and back up at once: the aim did not run away past −89
        rig.run(2);
        assertEquals(-89 + 100 * SENSITIVITY, rig.pose().pitch(), 1e-6);
    }

    @Test
    void yawWrapsIntoZeroTo360() {
        CameraRig rig = new CameraRig().at(0, 100, 0, 10, 0);
        rig.input.keyDown(GLFW_KEY_LEFT);
        rig.run(1.0 / 3);                   // 30° left of 10°: through north
        rig.input.keyUp(GLFW_KEY_LEFT);
        rig.run(1);
        assertEquals(340, rig.pose().yaw(), 1e-6);

        rig.at(0, 100, 0, 350, 0);
        rig.input.setLooking(true);
        rig.input.mouseMoved(20 / SENSITIVITY, 0);   // 20° right of 350°: the short way, through 0
        for (int i = 0; i < 60; i++) {
            rig.run(1.0 / 60);
            double yaw = rig.pose().yaw();
            assertTrue(yaw >= 0 && yaw < 360, "yaw in [0, 360): " + yaw);
            // the short way from 350° to 10° stays within that 20° arc; 0.001° for round-off at its ends
            assertTrue(yaw >= 349.999 || yaw <= 10.001, "turned the short way: " + yaw);
        }
        assertEquals(10, rig.pose().yaw(), 1e-3);
    }

    @Test
    void arrowKeysTurnAtTheTurnSpeed() {
        CameraRig rig = new CameraRig().at(0, 100, 0, 0, 0);
        rig.input.keyDown(GLFW_KEY_UP);
        rig.run(0.25);
        rig.input.keyUp(GLFW_KEY_UP);
        rig.run(1);
        assertEquals(0.25 * CameraSettings.DEFAULTS.turnSpeed(), rig.pose().pitch(), 1e-3);
    }
}

package org.openworld.engine.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_D;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_LEFT_SHIFT;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_RIGHT;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_SPACE;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_W;

import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/** Fly mode: inertia, terminal speed, glide, frame-rate independence. */
class CameraFlyTest {
    // Tolerances here: poses in double: set or closed-form values to 1e-9, sums over many steps to 1e-6; the bands on
    // speeds follow from the exponential damping (see each)

    private static final double FLY_SPEED = CameraSettings.DEFAULTS.flySpeed();

    @Test
    void holdingWAcceleratesAlongTheViewTowardsTheFlySpeed() {
        CameraRig rig = new CameraRig().at(0, 100, 0, 90, 20);
        rig.input.keyDown(GLFW_KEY_W);
        rig.run(1.0 / 60);
        double first = rig.speed();
        // one 1/60 s step of the acceleration reaches a small share of the fly speed: 20 % tells "some" from "all"
        assertTrue(first > 0 && first < 0.2 * FLY_SPEED, "one step gives some speed, not all of it: " + first);

        double previous = first;
        for (int i = 0; i < 5 * 60; i++) {
            rig.run(1.0 / 60);
            assertTrue(rig.speed() >= previous - 1e-9, "speed rises monotonically");
            assertTrue(rig.speed() <= FLY_SPEED + 1e-9, "never beyond the fly speed");
            previous = rig.speed();
        }
        assertEquals(FLY_SPEED, rig.speed(), 0.01 * FLY_SPEED, "terminal speed");
        Vector3d direction = new Vector3d(rig.system.controller().velocity()).normalize();
        Vector3d forward = CameraMath.forward(90, 20);
        // doubles: unit vectors from the same angles, equal to round-off
        assertEquals(1, direction.dot(forward), 1e-9, "moving along the view, " + direction);
        assertTrue(rig.pose().x() > 100 && rig.pose().y() > 100, "flew east and up: " + rig.pose());
    }

    @Test
    void shiftBoostsTheTerminalSpeed() {
        CameraRig rig = new CameraRig().at(0, 100, 0, 0, 0);
        rig.input.keyDown(GLFW_KEY_W);
        rig.input.keyDown(GLFW_KEY_LEFT_SHIFT);
        rig.run(5);
        assertEquals(FLY_SPEED * CameraSettings.DEFAULTS.boost(), rig.speed(), 0.01 * FLY_SPEED);
    }

    @Test
    void diagonalKeysAreNotFasterAndSpaceClimbs() {
        CameraRig rig = new CameraRig().at(0, 100, 0, 0, 0);
        rig.input.keyDown(GLFW_KEY_W);
        rig.input.keyDown(GLFW_KEY_D);
        rig.input.keyDown(GLFW_KEY_SPACE);
        rig.run(5);
        assertEquals(FLY_SPEED, rig.speed(), 0.01 * FLY_SPEED);
        Vector3d v = new Vector3d(rig.system.controller().velocity());
        assertTrue(v.x > 0 && v.y > 0 && v.z < 0, "north-east and up: " + v);
    }

    @Test
    void afterReleaseTheCameraGlidesToAHalt() {
        CameraRig rig = new CameraRig().at(0, 100, 0, 0, 0);
        rig.input.keyDown(GLFW_KEY_W);
        rig.run(3);
        double cruising = rig.speed();
        rig.input.keyUp(GLFW_KEY_W);
        rig.run(1.0 / 60);
        // one 1/60 s step of exponential damping keeps e^(-damping/60) of the speed, over 0.9; after five seconds e^(-5
        // damping), under 0.01 m/s; the closed form holds to 1e-6 (double steps)
        assertTrue(rig.speed() > 0.9 * cruising, "inertia: still moving after one step, " + rig.speed());
        double z = rig.pose().z();
        rig.run(1);
        assertTrue(rig.pose().z() < z - 5, "keeps gliding north for a while");
        rig.run(4);
        assertTrue(rig.speed() < 0.01, "near rest after five seconds: " + rig.speed());
        double damping = CameraSettings.DEFAULTS.damping();
        assertEquals(cruising * Math.exp(-damping * (5 + 1.0 / 60)), rig.speed(), 1e-6, "exponential decay");
    }

    @Test
    void theSameSimulatedTimeGivesTheSamePathAt60And120UpdatesPerSecond() {
        CameraPose at60 = flightWithATurn(1.0 / 60);
        CameraPose at120 = flightWithATurn(1.0 / 120);
        double distance = Math.hypot(at60.x(), at60.z());
        assertTrue(distance > 100, "the flight went somewhere: " + at60);
        double gap = Math.sqrt(Math.pow(at60.x() - at120.x(), 2) + Math.pow(at60.y() - at120.y(), 2)
                + Math.pow(at60.z() - at120.z(), 2));
        // the integrator's error is first order in the step: halving it moves a turning flight by a fraction of a
        // percent of its length; 0.5 % and 0.5° are the bounds chosen for "the same path"
        assertTrue(gap < 0.005 * distance, "positions differ by " + gap + " m over " + distance + " m");
        assertEquals(at60.yaw(), at120.yaw(), 0.5);
    }

    @Test
    void aStraightFlightIsExactlyFrameRateIndependent() {
        CameraPose at60 = straightFlight(1.0 / 60);
        CameraPose at120 = straightFlight(1.0 / 120);
        // doubles: a straight flight's closed form, equal to round-off over ~100 m
        assertEquals(at60.z(), at120.z(), 1e-6);
    }

    private static CameraPose straightFlight(double step) {
        CameraRig rig = new CameraRig().at(0, 100, 0, 0, 0);
        rig.input.keyDown(GLFW_KEY_W);
        rig.run(2, step);
        rig.input.keyUp(GLFW_KEY_W);
        rig.run(2, step);
        return rig.pose();
    }

    private static CameraPose flightWithATurn(double step) {
        CameraRig rig = new CameraRig().at(0, 100, 0, 0, 0);
        rig.input.keyDown(GLFW_KEY_W);
        rig.run(2, step);
        rig.input.keyDown(GLFW_KEY_RIGHT);
        rig.run(1, step);
        rig.input.keyUp(GLFW_KEY_RIGHT);
        rig.input.keyUp(GLFW_KEY_W);
        rig.run(2, step);
        return rig.pose();
    }

    @Test
    void flyingDownStopsAboveTheGround() {
        CameraRig rig = new CameraRig().at(0, 20, 0, 0, -60).ground((x, z) -> 5);
        rig.input.keyDown(GLFW_KEY_W);
        rig.run(5);
        // doubles: positions set exactly, equal to round-off
        assertEquals(5 + CameraController.MIN_CLEARANCE, rig.pose().y(), 1e-9);
        assertTrue(rig.system.controller().velocity().y() >= 0, "no speed into the ground is kept");
    }

    @Test
    void aNewDirectionStopsTheCamera() {
        CameraRig rig = new CameraRig().at(0, 100, 0, 0, 0);
        rig.input.keyDown(GLFW_KEY_W);
        rig.run(2);
        rig.input.keyUp(GLFW_KEY_W);
        CameraPose moving = rig.pose();
        rig.direct(CameraDirection.controls());   // the controls again, from where the camera is
        rig.run(1.0 / 60);
        assertEquals(0, rig.speed(), "taken up at rest");
        assertEquals(moving.z(), rig.pose().z(), 1e-9, "no glide after a new direction");

        rig.input.keyDown(GLFW_KEY_W);
        rig.run(2);
        rig.input.keyUp(GLFW_KEY_W);
        rig.at(500, 50, 500, 180, 10);   // a teleport
        rig.run(1);
        assertEquals(500, rig.pose().z(), 1e-9, "a pose set from outside carries no momentum");
        assertEquals(180, rig.pose().yaw(), 1e-9, "and the view does not swing back to the old aim");
        assertEquals(10, rig.pose().pitch(), 1e-9);
    }

    @Test
    void theFovSettingIsWrittenIntoThePose() {
        CameraRig rig = new CameraRig().at(0, 100, 0, 0, 0).set("camera.fov", "75");
        rig.run(1.0 / 60);
        assertEquals(75, rig.pose().fov());
    }
}

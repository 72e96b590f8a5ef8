package org.openworld.engine.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_LEFT_SHIFT;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_SPACE;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_V;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_W;

import org.junit.jupiter.api.Test;
import org.openworld.engine.core.HeightField;

/** Walk mode and switching modes. */
class CameraWalkTest {

    private static final double EYE = CameraSettings.DEFAULTS.eyeHeight();
    private static final double WALK = CameraSettings.DEFAULTS.walkSpeed();
    /** A hillside rising 1 m per 5 m towards the east. */
    private static final HeightField SLOPE = (x, z) -> 10 + 0.2 * x;

    @Test
    void vTogglesBetweenFlyAndWalk() {
        CameraRig rig = new CameraRig().at(0, 100, 0, 0, 0);
        rig.run(1.0 / 60);
        assertEquals(CameraMode.FLY, rig.system.controller().mode());
        rig.input.keyDown(GLFW_KEY_V);
        rig.run(1.0 / 60);
        assertEquals(CameraMode.WALK, rig.system.controller().mode());
        rig.run(1);
        assertEquals(CameraMode.WALK, rig.system.controller().mode(), "a held key toggles once");
        rig.input.keyUp(GLFW_KEY_V);
        rig.input.keyDown(GLFW_KEY_V);
        rig.run(1.0 / 60);
        assertEquals(CameraMode.FLY, rig.system.controller().mode());
    }

    @Test
    void switchingToWalkDropsToTheGround() {
        CameraRig rig = new CameraRig().at(0, 300, 0, 0, 0).ground(SLOPE);
        rig.input.keyDown(GLFW_KEY_V);
        rig.run(1.0 / 60);
        assertTrue(rig.pose().y() < 300 && rig.pose().y() > 10 + EYE, "on its way down: " + rig.pose().y());
        rig.run(2);
        // 1e-3 m: the eased eye height has converged after two seconds; speeds to 1e-3 m/s likewise
        assertEquals(10 + EYE, rig.pose().y(), 1e-3);
    }

    @Test
    void walkingKeepsTheEyeAtEyeHeightOverASlope() {
        CameraRig rig = new CameraRig().at(0, 10 + EYE, 0, 90, 30).ground(SLOPE).set("camera.mode", "walk");
        rig.input.keyDown(GLFW_KEY_W);
        rig.input.keyDown(GLFW_KEY_SPACE);   // no flying up while walking
        for (int i = 0; i < 10 * 60; i++) {
            rig.run(1.0 / 60);
            CameraPose p = rig.pose();
            double ground = SLOPE.heightAt(p.x(), p.z());
            assertTrue(p.y() >= ground, "never below the ground");
            if (i > 60) {
                // 5 cm: the eased eye trails a rising slope by its lag at walking pace, a few centimetres, well under a
                // step
                assertEquals(ground + EYE, p.y(), 0.05, "eye height at x = " + p.x());
            }
        }
        CameraPose p = rig.pose();
        assertEquals(10 * WALK, p.x(), 0.05 * 10 * WALK, "walked east at walking speed, not along the 30° view");
        // doubles: no sideways component at all, equal to round-off
        assertEquals(0, p.z(), 1e-9);
        assertEquals(WALK, rig.speed(), 1e-3);
        assertEquals(0, rig.system.controller().velocity().y(), 0);
    }

    @Test
    void aStepInTheGroundIsFollowedSmoothlyAndNeverFromBelowTheGround() {
        HeightField step = (x, z) -> x < 1 ? 0 : 1;   // a 1 m step up, 1 m east
        CameraRig rig = new CameraRig().at(0, EYE, 0, 90, 0).ground(step).set("camera.mode", "walk");
        rig.input.keyDown(GLFW_KEY_W);
        rig.input.keyDown(GLFW_KEY_LEFT_SHIFT);
        double previous = rig.pose().y();
        double biggestRise = 0;
        for (int i = 0; i < 3 * 60; i++) {
            rig.run(1.0 / 60);
            CameraPose p = rig.pose();
            assertTrue(p.y() >= step.heightAt(p.x(), p.z()) + CameraController.MIN_CLEARANCE - 1e-9, "above the ground");
            biggestRise = Math.max(biggestRise, p.y() - previous);
            previous = p.y();
        }
        // eased, not a jump: no update rises by more than half the 1 m step
        assertTrue(biggestRise < 0.5, "the 1 m step is eased in, largest rise per update " + biggestRise);
        assertEquals(1 + EYE, rig.pose().y(), 1e-3);
        assertEquals(WALK * CameraSettings.DEFAULTS.runFactor(), rig.speed(), 1e-3, "Shift runs");
    }

    @Test
    void walkingStopsPromptlyWhenTheKeyIsReleased() {
        CameraRig rig = new CameraRig().at(0, EYE, 0, 0, 0).set("camera.mode", "walk");
        rig.input.keyDown(GLFW_KEY_W);
        rig.run(2);
        rig.input.keyUp(GLFW_KEY_W);
        rig.run(1.5);
        // 1 % of walking speed: a stop, left to the exponential's tail after 1.5 s
        assertTrue(rig.speed() < 0.01 * WALK, "stopped: " + rig.speed());
    }

    @Test
    void withoutAHeightFieldTheGroundIsFlatAtSeaLevel() {
        CameraRig rig = new CameraRig().at(0, 50, 0, 0, 0).set("camera.mode", "walk");
        rig.run(3);
        assertEquals(EYE, rig.pose().y(), 1e-3);
    }
}

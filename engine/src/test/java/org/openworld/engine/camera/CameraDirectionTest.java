package org.openworld.engine.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_W;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.openworld.engine.core.HeightField;

/** The director: each kind of direction, how a new one is taken up, and that it alone writes the camera. */
class CameraDirectionTest {

    private static final double STEP = 1.0 / 60;
    /** A straight flight east at 10 m/s from t = 2 s to t = 12 s, 100 m above the ground. */
    private static final CameraPath EAST = new CameraPath(HeightReference.GROUND, List.of(
            new Keyframe(2, 0, 100, 0, 90, 0, 60),
            new Keyframe(7, 50, 100, 0, 90, 0, 60),
            new Keyframe(12, 100, 100, 0, 90, 0, 60)));

    @Test
    void aFixedPoseHoldsFromTheFirstUpdate() {
        CameraPose pose = new CameraPose(10, 2500, -40, 45, -5, 70);
        CameraRig rig = new CameraRig().direct(CameraDirection.fixed(pose));
        rig.input.keyDown(GLFW_KEY_W);
        rig.run(STEP, STEP);
        assertEquals(pose, rig.pose(), "the first update already puts the camera there");
        rig.run(1);
        assertEquals(pose, rig.pose(), "and the controls do not move it");
    }

    @Test
    void aReplayShowsThePathAtKStepsOnTheKthUpdate() {
        HeightField hill = (x, z) -> 0.5 * x;
        CameraRig rig = new CameraRig().ground(hill).direct(CameraDirection.play(EAST, EAST.startTime(), false));
        for (int k = 0; k < 90; k++) {
            rig.run(STEP, STEP);
            assertEquals(EAST.sample(2 + k * STEP, hill), rig.pose(), "update " + k);
        }
        rig.run(20);
        assertEquals(EAST.sample(12, hill), rig.pose(), "past the end the last pose holds");
    }

    @Test
    void aLoopedReplayStartsAgainAfterItsLastKey() {
        CameraRig rig = new CameraRig().direct(CameraDirection.play(EAST, 11, true));
        rig.run(STEP * 181, STEP);   // t = 11 + 180/60 = 14 s: 2 s past the end, so 2 s past the start
        // doubles: the same sample taken twice, equal to round-off
        assertEquals(EAST.sample(4, HeightField.FLAT).x(), rig.pose().x(), 1e-9);
    }

    @Test
    void aHeldMomentStandsStill() {
        CameraRig rig = new CameraRig().direct(CameraDirection.hold(EAST, 7));
        rig.run(1);
        assertEquals(EAST.sample(7, HeightField.FLAT), rig.pose());
    }

    @Test
    void theControlsTakeOverAtRestWhereThePathLeftTheCamera() {
        CameraRig rig = new CameraRig().direct(CameraDirection.play(EAST, 2, false));
        rig.run(1);
        CameraPose left = rig.pose();
        rig.direct(CameraDirection.controls()).run(STEP, STEP);
        assertEquals(left.x(), rig.pose().x(), 1e-9, "no jump and no momentum from the path");
        assertEquals(left.yaw(), rig.pose().yaw(), 1e-9, "the view stays on the path's heading");
        assertEquals(0, rig.speed());
    }

    @Test
    void aWorldWithoutADirectionIsUnderTheControls() {
        CameraRig rig = new CameraRig();
        rig.input.keyDown(GLFW_KEY_W);
        rig.run(1);
        assertTrue(rig.world.resource(CameraDirection.class) instanceof CameraDirection.Controls);
        assertTrue(rig.speed() > 0, "the keys move the camera");
    }

    @Test
    void aRebuiltWorldCarriesTheDirectionOver() {
        CameraPose here = new CameraPose(1, 2, 3, 4, 5, 60);
        assertEquals(CameraDirection.controlsFrom(here), CameraDirection.controls().carriedOver(here));
        CameraDirection replay = CameraDirection.play(EAST, 2, true);
        assertSame(replay, replay.carriedOver(here));
    }

    @Test
    void aReplayNeedsAFiniteStartAndNoBackwardRate() {
        assertThrows(IllegalArgumentException.class, () -> new CameraDirection.Replay(EAST, Double.NaN, 1, false));
        assertThrows(IllegalArgumentException.class, () -> new CameraDirection.Replay(EAST, 2, -1, false));
    }

    @Test
    void theDirectorReadsTheDirectionAndAloneWritesTheCamera() {
        CameraSystem director = new CameraSystem();
        assertTrue(director.spec().reads().contains(CameraDirection.class));
        assertEquals(java.util.Set.of(Camera.class), director.spec().writes());
    }
}

package org.openworld.engine.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.openworld.engine.core.HeightField;

class CameraPathTest {

    private static final double EPS = 1e-9;
    /** Sampling step for the continuity checks, seconds. */
    private static final double STEP = 0.001;

    /** Yaw goes 350 → 10 → 350 through north, then 250 → 170 → 190 → 170 through south. */
    private static final CameraPath TURNS = new CameraPath(HeightReference.SEA, List.of(
            new Keyframe(0, 0, 100, 0, 350, 0, 60),
            new Keyframe(1, 40, 110, -10, 10, 10, 60),
            new Keyframe(2.5, 60, 120, -60, 350, -20, 50),
            new Keyframe(3, 61, 120, -70, 250, -30, 50),
            new Keyframe(4, 40, 100, -90, 170, -10, 55),
            new Keyframe(5, 0, 90, -100, 190, 5, 70),
            new Keyframe(6, -30, 80, -90, 170, 0, 60)));

    @Test
    void passesThroughEveryKeyAtItsTime() {
        for (Keyframe key : TURNS.keys()) {
            CameraPose pose = TURNS.sample(key.time(), HeightField.FLAT);
            assertEquals(key.x(), pose.x(), EPS);
            assertEquals(key.y(), pose.y(), EPS);
            assertEquals(key.z(), pose.z(), EPS);
            assertEquals(0, angleBetween(key.yaw(), pose.yaw()), EPS);
            assertEquals(key.pitch(), pose.pitch(), EPS);
            assertEquals(key.fov(), pose.fov(), EPS);
        }
    }

    @Test
    void clampsBeforeTheStartAndAfterTheEnd() {
        assertEquals(TURNS.sample(0, HeightField.FLAT), TURNS.sample(-3, HeightField.FLAT));
        assertEquals(TURNS.sample(6, HeightField.FLAT), TURNS.sample(60, HeightField.FLAT));
        assertEquals(6, TURNS.duration(), EPS);
    }

    @Test
    void positionHasNoJumps() {
        double maxSegmentSpeed = 0;
        List<Keyframe> keys = TURNS.keys();
        for (int i = 1; i < keys.size(); i++) {
            Keyframe a = keys.get(i - 1);
            Keyframe b = keys.get(i);
            double chord = Math.sqrt(sq(b.x() - a.x()) + sq(b.y() - a.y()) + sq(b.z() - a.z()));
            maxSegmentSpeed = Math.max(maxSegmentSpeed, chord / (b.time() - a.time()));
        }
        // a Catmull-Rom segment may move faster than its chord's average speed, but only by a small factor
        double bound = 4 * maxSegmentSpeed * STEP;
        CameraPose previous = TURNS.sample(0, HeightField.FLAT);
        for (double t = STEP; t <= TURNS.duration(); t += STEP) {
            CameraPose pose = TURNS.sample(t, HeightField.FLAT);
            double jump = Math.sqrt(sq(pose.x() - previous.x()) + sq(pose.y() - previous.y())
                    + sq(pose.z() - previous.z()));
            assertTrue(jump <= bound, "position jumped " + jump + " m at t=" + t + " (bound " + bound + ")");
            previous = pose;
        }
    }

    @Test
    void anglesHaveNoJumpsOrFlips() {
        CameraPose previous = TURNS.sample(0, HeightField.FLAT);
        for (double t = STEP; t <= TURNS.duration(); t += STEP) {
            CameraPose pose = TURNS.sample(t, HeightField.FLAT);
            assertTrue(pose.yaw() >= 0 && pose.yaw() < 360, "yaw " + pose.yaw() + " outside [0, 360)");
            // under 1° a sample step: the paths turn by a few degrees a second, so a flip (180°) or wrap error (360°)
            // stands far out
            assertTrue(angleBetween(previous.yaw(), pose.yaw()) < 1, "yaw jumped at t=" + t);
            assertTrue(Math.abs(pose.pitch() - previous.pitch()) < 1, "pitch jumped at t=" + t);
            assertTrue(Math.abs(pose.fov() - previous.fov()) < 1, "fov jumped at t=" + t);
            previous = pose;
        }
    }

    @Test
    void yawTakesTheShortTurnBetweenKeys() {
        List<Keyframe> keys = TURNS.keys();
        for (int i = 1; i < keys.size(); i++) {
            Keyframe a = keys.get(i - 1);
            Keyframe b = keys.get(i);
            double halfTurn = angleBetween(a.yaw(), b.yaw()) / 2;
            double middle = a.yaw() + signedTurn(a.yaw(), b.yaw()) / 2;
            for (double t = a.time(); t <= b.time(); t += STEP) {
                double yaw = TURNS.sample(t, HeightField.FLAT).yaw();
                // within the short arc, never past a key; going the long way round would pass 180° off its middle
                assertTrue(angleBetween(middle, yaw) <= halfTurn + 1e-9,
                        "yaw " + yaw + " at t=" + t + " left the short arc " + a.yaw() + " → " + b.yaw());
            }
        }
        assertEquals(0, angleBetween(0, TURNS.sample(0.5, HeightField.FLAT).yaw()), 3);
        assertEquals(0, angleBetween(180, TURNS.sample(4.5, HeightField.FLAT).yaw()), 3);
    }

    @Test
    void coincidentKeyframesGiveFiniteValues() {
        CameraPath hover = new CameraPath(HeightReference.SEA, List.of(
                new Keyframe(0, 5, 50, 5, 0, 0, 60),
                new Keyframe(1, 5, 50, 5, 90, 0, 60),
                new Keyframe(2, 5, 50, 5, 180, 0, 60),
                new Keyframe(3, 25, 50, 5, 180, 0, 60),
                new Keyframe(4, 25, 50, 5, 180, 0, 60)));
        for (double t = 0; t <= 4; t += 0.01) {
            CameraPose pose = hover.sample(t, HeightField.FLAT);
            for (double v : new double[] {pose.x(), pose.y(), pose.z(), pose.yaw(), pose.pitch(), pose.fov()}) {
                assertTrue(Double.isFinite(v), "t=" + t + " gave " + pose);
            }
        }
        // doubles: linear interpolation between keys, to round-off
        assertEquals(5, hover.sample(1.5, HeightField.FLAT).x(), 1e-6);
        assertEquals(25, hover.sample(3.5, HeightField.FLAT).x(), 1e-6);
    }

    @Test
    void groundHeightsFollowTheTerrain() {
        HeightField slope = (x, z) -> 0.2 * x - 0.1 * z + 30;
        CameraPath walk = new CameraPath(HeightReference.GROUND, List.of(
                new Keyframe(0, 0, 1.7, 0, 90, 0, 60),
                new Keyframe(5, 7, 1.7, 2, 80, 0, 60),
                new Keyframe(10, 14, 1.7, -3, 100, 0, 60)));
        for (double t = 0; t <= 10; t += 0.1) {
            CameraPose pose = walk.sample(t, slope);
            assertEquals(slope.heightAt(pose.x(), pose.z()) + 1.7, pose.y(), EPS, "t=" + t);
        }
    }

    @Test
    void rejectsTooFewKeysAndTimesThatDoNotIncrease() {
        Keyframe a = new Keyframe(1, 0, 0, 0, 0, 0, 60);
        assertThrows(IllegalArgumentException.class, () -> new CameraPath(HeightReference.SEA, List.of(a)));
        assertThrows(IllegalArgumentException.class, () -> new CameraPath(HeightReference.SEA, List.of(a, a)));
    }

    /** The unsigned angle between two directions, [0, 180] degrees. */
    static double angleBetween(double a, double b) {
        return Math.abs(signedTurn(a, b));
    }

    /** The shorter turn from a to b, (-180, 180] degrees. */
    static double signedTurn(double a, double b) {
        double d = ((b - a) % 360 + 360) % 360;
        return d > 180 ? d - 360 : d;
    }

    private static double sq(double v) {
        return v * v;
    }
}

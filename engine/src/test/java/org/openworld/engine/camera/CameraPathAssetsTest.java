package org.openworld.engine.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.openworld.engine.core.HeightField;

/** The paths shipped in assets/paths/ parse from the classpath and do what their headers promise. */
class CameraPathAssetsTest {
    // Tolerances here: poses in double: exact keys and sums to 1e-9, sums over many samples to 1e-6; bands on the
    // paths' heights and speeds are the assets' own design, asserted

    /** Half the world's width, metres. */
    private static final double WORLD_HALF_WIDTH = 2048;

    @Test
    void valleyIsALowFlightNearTheCentre() throws CameraPathFormatException {
        CameraPath valley = CameraPathParser.parseResource("assets/paths/valley.path");
        assertEquals(HeightReference.GROUND, valley.heights());
        assertEquals(30, valley.duration(), 1e-9);
        HeightField hills = (x, z) -> 300 + 20 * Math.sin(x / 10) * Math.cos(z / 15);
        for (double t = 0; t <= valley.duration(); t += 0.1) {
            CameraPose pose = valley.sample(t, hills);
            double above = pose.y() - hills.heightAt(pose.x(), pose.z());
            // the valley path's keys are 60–200 m above the ground and within 1.5 km of the centre: the path's own
            // design, asserted
            assertTrue(above >= 60 && above <= 200, "height above ground " + above + " at t=" + t);
            assertTrue(Math.abs(pose.x()) <= 1500 && Math.abs(pose.z()) <= 1500, pose + " at t=" + t);
        }
    }

    @Test
    void driftIsSlowEnoughForFlickerMeasures() throws CameraPathFormatException {
        CameraPath drift = CameraPathParser.parseResource("assets/paths/drift.path");
        double step = 1.0 / 60; // bench: one fixed step per frame
        CameraPose previous = drift.sample(0, HeightField.FLAT);
        for (double t = step; t <= drift.duration(); t += step) {
            CameraPose pose = drift.sample(t, HeightField.FLAT);
            double moved = Math.hypot(Math.hypot(pose.x() - previous.x(), pose.y() - previous.y()),
                    pose.z() - previous.z());
            // a slow drift for flicker measures: under 10 cm and 0.05° a frame at 60 frames a second (6 m/s, 3°/s);
            // bounds chosen, not derived
            assertTrue(moved < 0.1, "moved " + moved + " m in one frame at t=" + t);
            assertTrue(Math.abs(pose.yaw() - previous.yaw()) < 0.05, "turned too fast at t=" + t);
            previous = pose;
        }
    }

    @Test
    void walkStaysAtEyeHeightAtWalkingPace() throws CameraPathFormatException {
        CameraPath walk = CameraPathParser.parseResource("assets/paths/walk.path");
        assertEquals(HeightReference.GROUND, walk.heights());
        HeightField hills = (x, z) -> 300 + 20 * Math.sin(x / 10) * Math.cos(z / 15);
        double length = 0;
        CameraPose previous = walk.sample(0, hills);
        for (double t = 0.01; t <= walk.duration(); t += 0.01) {
            CameraPose pose = walk.sample(t, hills);
            // doubles: the ground height plus the 1.7 m eye height, equal to round-off
            assertEquals(hills.heightAt(pose.x(), pose.z()) + 1.7, pose.y(), 1e-9);
            length += Math.hypot(pose.x() - previous.x(), pose.z() - previous.z());
            previous = pose;
        }
        assertEquals(45, length, 1);
        // 1.5 m/s, a walking pace; 45 m to a metre and 0.05 m/s: the 0.01 s sampling of a curved path shortens it a
        // little
        assertEquals(1.5, length / walk.duration(), 0.05);
    }

    @Test
    void orbitCirclesTheOriginLookingAtIt() throws CameraPathFormatException {
        CameraPath orbit = CameraPathParser.parseResource("assets/paths/orbit.path");
        assertEquals(40, orbit.duration(), 1e-9);
        double turned = 0;
        double previousBearing = 0;
        for (int step = 0; step <= 4000; step++) {
            double t = step * 0.01;
            CameraPose pose = orbit.sample(t, HeightField.FLAT);
            double radius = Math.hypot(pose.x(), pose.z());
            // the first and last segments bend inside the circle (about 17 m): a path's ends continue straight
            boolean endSegment = t < 2.5 || t > 37.5;
            assertEquals(1500, radius, endSegment ? 20 : 1.5, "radius at t=" + t);
            assertTrue(radius < WORLD_HALF_WIDTH);
            assertEquals(1500, pose.y(), 1e-9);
            assertEquals(-25, pose.pitch(), 1e-9);
            double towardCentre = Math.toDegrees(Math.atan2(-pose.x(), pose.z()));
            assertEquals(0, CameraPathTest.angleBetween(towardCentre, pose.yaw()), 2, "yaw at t=" + t);
            double bearing = Math.toDegrees(Math.atan2(pose.x(), -pose.z()));
            turned += CameraPathTest.signedTurn(previousBearing, bearing);
            previousBearing = bearing;
        }
        // doubles: angles summed over the orbit's samples, to round-off (1e-6 to 1e-9)
        assertEquals(360, turned, 1e-6);
    }

    /** Ground for the crossings: they must keep 400 m above whatever lies below. */
    private static final HeightField HILLS = (x, z) -> 300 * Math.sin(x / 700) * Math.cos(z / 900);

    @Test
    void crossingFliesEighteenKilometresDueEastAtThreeHundredMetresASecondFourHundredAboveTheGround()
            throws CameraPathFormatException {
        fliesDueEast(CameraPathParser.parseResource("assets/paths/crossing.path"), 60);
    }

    /** The memory check's path: {@code crossing.path} flown on, to 36 km at 120 s. */
    @Test
    void crossingTwiceIsTheCrossingFlownOnToThirtySixKilometres() throws CameraPathFormatException {
        fliesDueEast(CameraPathParser.parseResource("assets/paths/crossing-twice.path"), 120);
    }

    /**
     * The path lasts {@code seconds} and flies from x = −9 km due east at 300 m/s, 400 m above the ground, looking
     * ahead and 8° down, all the way.
     */
    private static void fliesDueEast(CameraPath path, double seconds) {
        assertEquals(seconds, path.duration(), 1e-9);
        for (int step = 0; step <= Math.round(seconds * 10); step++) {
            double t = step * 0.1;
            CameraPose pose = path.sample(t, HILLS);
            assertEquals(-9000 + 300 * t, pose.x(), 1e-6, "a straight line at 300 m/s, t=" + t);
            assertEquals(0, pose.z(), 1e-9);
            assertEquals(400, pose.y() - HILLS.heightAt(pose.x(), pose.z()), 1e-6, "400 m above the ground");
            assertEquals(90, pose.yaw(), 1e-9);
            assertEquals(-8, pose.pitch(), 1e-9);
        }
    }
}

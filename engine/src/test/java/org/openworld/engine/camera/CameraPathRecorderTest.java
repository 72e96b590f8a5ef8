package org.openworld.engine.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Path;
import java.time.Clock;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CameraPathRecorderTest {

    /** The engine's fixed simulation step, seconds. */
    private static final double STEP = 1.0 / 60;

    @Test
    void keepsOneKeyPerIntervalOfSimulationTime() {
        CameraPathRecorder recorder = new CameraPathRecorder(0.25);
        double simTime = 100; // recording starts in the middle of a session
        for (int step = 0; step <= 120; step++) {
            recorder.record(simTime, pose(step));
            simTime += STEP;
        }
        List<Keyframe> keys = recorder.toPath().keys();
        assertEquals(9, keys.size()); // 0, 0.25, ..., 2.0 s
        for (int i = 0; i < keys.size(); i++) {
            // doubles: times of exact steps, to round-off
            assertEquals(i * 0.25, keys.get(i).time(), 1e-9);
            assertEquals(i * 15, keys.get(i).x(), 1e-9); // the pose of step 15 i
        }
    }

    @Test
    void takesTheFirstStepAtOrPastEachMultipleWhenStepsDoNotDivideTheInterval() {
        CameraPathRecorder recorder = new CameraPathRecorder(0.25);
        for (int step = 0; step <= 10; step++) {
            recorder.record(step * 0.1, pose(step));
        }
        double[] expected = {0, 0.3, 0.5, 0.8, 1.0};
        List<Keyframe> keys = recorder.toPath().keys();
        assertEquals(expected.length, keys.size());
        for (int i = 0; i < expected.length; i++) {
            assertEquals(expected[i], keys.get(i).time(), 1e-9);
        }
    }

    @Test
    void needsTwoKeysForAPath() {
        CameraPathRecorder recorder = new CameraPathRecorder(CameraPathRecorder.DEFAULT_INTERVAL);
        recorder.record(0, pose(0));
        recorder.record(0.1, pose(1));
        assertEquals(1, recorder.size());
        assertThrows(IllegalStateException.class, recorder::toPath);
        assertThrows(IllegalArgumentException.class, () -> new CameraPathRecorder(0));
    }

    @Test
    void savesATimestampedFileThatParsesBack(@TempDir Path dir) throws Exception {
        CameraPathRecorder recorder = new CameraPathRecorder(0.5);
        for (int step = 0; step < 5; step++) {
            recorder.record(step * 0.5, pose(step));
        }
        Clock clock = Clock.fixed(Instant.parse("2024-01-02T03:04:05Z"), ZoneOffset.UTC);
        Path file = recorder.save(dir.resolve("paths"), clock);
        assertEquals(dir.resolve("paths/recorded-20240102-030405.path"), file);
        CameraPath back = CameraPathParser.parse(file);
        assertEquals(HeightReference.SEA, back.heights());
        assertEquals(recorder.toPath().keys(), back.keys());
        assertThrows(FileAlreadyExistsException.class, () -> recorder.save(dir.resolve("paths"), clock));
    }

    /** A pose that moves 1 m east per step and turns 3° per step. */
    private static CameraPose pose(int step) {
        return new CameraPose(step, 120, -step * 0.5, (step * 3) % 360, -10, 60);
    }
}

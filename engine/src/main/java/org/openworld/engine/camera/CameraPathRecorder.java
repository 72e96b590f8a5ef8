package org.openworld.engine.camera;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Clock;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;

/**
 * Records the camera as a path: fed the pose at every simulation step, it keeps one key per interval of simulation
 * time, so the recording does not depend on the frame rate and replays identically. Key times start at 0 with the
 * first recorded pose; y is above sea level.
 */
public final class CameraPathRecorder {

    /** Simulation time between recorded keys, seconds: enough keys for the curve to follow a hand-flown camera. */
    public static final double DEFAULT_INTERVAL = 0.25;

    /** Shortest interval, seconds: the time precision of the file format. */
    public static final double MIN_INTERVAL = 0.001;

    /** Slack on the due time, seconds: a sum of fixed steps such as 15 × 1/60 may land a hair short of 0.25. */
    private static final double TIME_TOLERANCE = 1e-9;

    private static final DateTimeFormatter FILE_STAMP = DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss");

    private final double interval;
    private final List<Keyframe> keys = new ArrayList<>();
    private double startTime;

    /** @param intervalSeconds simulation time between keys, at least {@link #MIN_INTERVAL} */
    public CameraPathRecorder(double intervalSeconds) {
        if (!(intervalSeconds >= MIN_INTERVAL)) {
            throw new IllegalArgumentException("interval must be at least 0.001 s: " + intervalSeconds);
        }
        this.interval = intervalSeconds;
    }

    /**
     * Offers the camera at one simulation step. The first pose is always kept; after that, the first pose at or
     * past each multiple of the interval.
     *
     * @param simSeconds the engine's simulation time, seconds, not decreasing between calls
     */
    public void record(double simSeconds, CameraPose pose) {
        if (keys.isEmpty()) {
            startTime = simSeconds;
        }
        double elapsed = simSeconds - startTime;
        if (keys.isEmpty() || elapsed >= keys.size() * interval - TIME_TOLERANCE) {
            keys.add(Keyframe.of(elapsed, pose));
        }
    }

    /** Keys recorded so far. */
    public int size() {
        return keys.size();
    }

    /**
     * The recording as a path measured from sea level.
     *
     * @throws IllegalStateException before two keys have been recorded
     */
    public CameraPath toPath() {
        if (keys.size() < 2) {
            throw new IllegalStateException("a recording needs at least 2 keys, has " + keys.size());
        }
        return new CameraPath(HeightReference.SEA, keys);
    }

    /**
     * Writes the recording into {@code directory} (created if missing) as {@code recorded-YYYYMMDD-HHMMSS.path}.
     * An existing file is never overwritten.
     *
     * @param clock gives the local date and time for the name
     * @return the file written
     * @throws java.nio.file.FileAlreadyExistsException if a recording was saved there in the same second
     */
    public Path save(Path directory, Clock clock) throws IOException {
        Files.createDirectories(directory);
        Path file = directory.resolve("recorded-" + FILE_STAMP.format(LocalDateTime.now(clock)) + ".path");
        return Files.writeString(file, CameraPathWriter.format(toPath()), StandardOpenOption.CREATE_NEW);
    }
}

package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.openworld.engine.bench.FrameRecord;
import org.openworld.engine.camera.CameraDirection;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.terrain.heights.TerrainSettings;
import picocli.CommandLine;

/**
 * A profiled frame ({@code bench --profile}) is split by its spans: every span finishes the GPU before it ends, so the
 * wall time outside the spans is only the engine's CPU work between them (binding the frame block, each system's
 * beginPass) and the throttle's fence wait, which is about zero when the GPU is already idle. If a part of the frame
 * were not in a span (a pass's clear, an update), its time would fall between spans and the sum would come short.
 * On both worlds: the unbounded one's update uploads streamed blocks that must fall in its span too.
 */
@Tag("gl")
class ProfiledFrameTest {

    /** Frames before the measured ones: shaders compiled, first uploads made, the first frame's interval excluded. */
    private static final int WARMUP = 3;
    private static final int FRAMES = 8;

    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    void theSpansOfAProfiledFrameAddUpToItsFrameTime(TerrainSettings.World world) {
        List<FrameRecord> records = new ArrayList<>();
        ShotCommand shot = new ShotCommand();
        // every cascade redrawn every frame, so each frame has a SHADOW pass to split (the default keeps maps whose
        // box did not move, and this camera stands still)
        new CommandLine(shot).parseArgs("--size", "320x180", "--set", "terrain.size=256",
                "--set", "shadow.refresh=always", "--set", "terrain.world=" + world, "--out", "unused.png");
        try (Launch launch = Launch.start(shot.render, false, "test")) {
            launch.engine.profile();
            double ground = launch.engine.world().resource(HeightField.class).heightAt(-300, 700);
            Poses.direct(launch.engine.world(), CameraDirection.fixed(new CameraPose(-300, ground + 100, 700, 20, -8,
                    CameraPose.DEFAULT_FOV)));
            for (int frame = 0; frame < WARMUP + FRAMES; frame++) {
                launch.engine.update();
                launch.engine.render();
                launch.engine.collectFrames(false, r -> {
                    if (r.frame() >= WARMUP) {
                        records.add(r);
                    }
                });
            }
            launch.engine.collectFrames(true, records::add);
        }

        assertTrue(records.size() == FRAMES, () -> records.size() + " frames recorded");
        List<Double> shares = new ArrayList<>();
        for (FrameRecord r : records) {
            double spans = r.passGpuMs().values().stream().mapToDouble(Double::doubleValue).sum();
            double share = spans / r.wallMs();
            // the spans are disjoint parts of the frame's interval, timed by the same clock
            assertTrue(share <= 1.0, () -> "frame " + r.frame() + ": spans " + spans + " ms in a frame of " + r.wallMs()
                    + " ms: " + r.passGpuMs());
            shares.add(share);
        }
        double median = shares.stream().sorted().toList().get(FRAMES / 2);
        // the passes are the frame: what the spans leave out is the CPU's work between them, a tenth at most in the
        // median frame
        assertTrue(median >= 0.9, () -> "the spans cover a median " + median + " of the frame time: " + shares
                + "\n" + records.get(0).passGpuMs());

        // every pass's own part (binding and clearing its target) is a span, as are the updates
        Set<String> spans = new TreeSet<>(records.get(0).passGpuMs().keySet());
        for (String span : spans) {
            String pass = span.substring(0, span.indexOf('.'));
            if (!pass.equals("update")) {
                assertTrue(spans.contains(pass + ".engine"), () -> span + " without " + pass + ".engine in " + spans);
            }
        }
        assertTrue(spans.containsAll(List.of("main.engine", "main.terrain", "main.sky", "shadow0.engine",
                "reflection.engine", "update.terrain", "update.sky")), spans::toString);
        assertFalse(records.get(0).passGpuMs().values().stream().anyMatch(ms -> ms < 0), spans::toString);
    }
}

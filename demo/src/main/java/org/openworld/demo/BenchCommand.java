package org.openworld.demo;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.openworld.engine.camera.CameraController;
import org.openworld.engine.camera.CameraDirection;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.bench.BenchComparison;
import org.openworld.engine.bench.BenchReport;
import org.openworld.engine.bench.FrameRecord;
import org.openworld.engine.bench.FrameTimeChart;
import org.openworld.engine.bench.MemoryMeter;
import org.openworld.engine.bench.RunInfo;
import org.openworld.engine.bench.Summary;
import org.openworld.engine.camera.CameraPath;
import org.openworld.engine.camera.CameraPathParser;
import org.openworld.engine.camera.CameraSystem;
import org.openworld.engine.gl.GpuMemoryInfo;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code openworld bench}: replays a camera path at the fixed step, one step per frame, and writes
 * {@code frames.csv}, {@code summary.json} and {@code frametime.png} (docs/benchmarks.md). With {@code --compare}
 * it prints two earlier runs side by side instead.
 *
 * <p>Nothing is lost: {@code --out} is checked before the world is made ({@link Outputs#runFolder}); the three files
 * replace the earlier run together ({@link BenchReport#write}); and SIGINT or SIGTERM during the frames
 * ({@link StopSignal}) stops the loop and writes the frames measured so far as a partial run ({@code "complete":
 * false}), then the JVM exits with 130 or 143. With {@code --discard-partial} a stopped run writes nothing and the
 * earlier run stays.
 */
@Command(name = "bench", mixinStandardHelpOptions = true, description = "Replay a camera path and record per-frame timings, or compare two runs.")
final class BenchCommand implements Callable<Integer> {

    @Mixin
    RenderOptions render;

    @Option(names = "--path", paramLabel = "FILE", description = "The camera path to replay.")
    Path path;

    @Option(names = "--out", paramLabel = "DIR", description = "Output folder (default: ${DEFAULT-VALUE}).",
            defaultValue = "bench-out")
    Path out;

    @Option(names = "--frames", paramLabel = "N",
            description = "Frames to record (default: the whole path at the fixed step).")
    Integer frames;

    @Option(names = "--warmup", paramLabel = "N", description = "Frames rendered first and not recorded (default: ${DEFAULT-VALUE}).",
            defaultValue = "30")
    int warmup;

    @Option(names = "--compare", arity = "2", paramLabel = "SUMMARY.json",
            description = "Compare two summary.json files: each metric side by side with the ratio B/A.")
    List<Path> compare;

    @Option(names = "--profile",
            description = "Finish the GPU around every span and record its wall time in place of the timer query: "
                    + "an exact split of the frame on any driver, for a slower, serialised frame.")
    boolean profile;

    @Option(names = "--discard-partial",
            description = "On SIGINT or SIGTERM, write nothing and keep the earlier run (default: write the frames "
                    + "measured so far as a partial run).")
    boolean discardPartial;

    /** Most frames of one run, warm-up included: about 4.6 hours at 60 fps, every record held in memory. */
    static final int MAX_FRAMES = 1_000_000;

    /** Longest silence between two progress lines: 10 s, so a slow machine's run still shows it is alive. */
    private static final long PROGRESS_EVERY_NS = 10_000_000_000L;

    /** The fixed simulation step of this run, seconds. */
    private double step;

    @Override
    public Integer call() throws Exception {
        if (compare != null) {
            System.out.print(BenchComparison.read(compare.get(0), compare.get(1)).table());
            return 0;
        }
        if (path == null) {
            throw new UserError("bench needs --path FILE (e.g. assets/paths/valley.path), or --compare A B");
        }
        if (warmup < 0 || (frames != null && frames < 1)) {
            throw new UserError("--frames must be at least 1 and --warmup at least 0");
        }
        CameraPath cameraPath = CameraPathParser.parse(path);
        checkFrameCount(cameraPath);
        Outputs.runFolder(out, BenchReport.FILES);
        FrameTimeChart.warmUpInBackground(); // while the world is built, so a stopped run writes its chart quickly
        try (Launch launch = Launch.start(render, render.windowed(false), "OpenWorld bench");
             StopSignal stop = StopSignal.install()) {
            var engine = launch.engine;
            step = engine.settings().get(EngineSettings.class).step();
            if (profile) {
                engine.profile();
            }
            int recorded = frames != null ? frames : (int) Math.floor(cameraPath.duration() / step) + 1;
            List<FrameRecord> records = new ArrayList<>();
            int total = warmup + recorded;
            int reportEvery = Math.max(1, total / 10);
            long lastReport = System.nanoTime();
            System.err.printf("bench: %s, %d warm-up + %d frames at %dx%d on %s%n", path, warmup, recorded,
                    engine.width(), engine.height(), launch.gl.renderer());
            // Warm-up frames hold the path's first pose; recorded frame k shows the path at k steps.
            Poses.direct(engine.world(), CameraDirection.hold(cameraPath, cameraPath.startTime()));
            MemoryMeter memory = new MemoryMeter(GpuMemoryInfo.of(), launch.gl.textureMemory());
            int rendered = 0; // frames rendered: total, unless a signal stopped the run
            for (; rendered < total && !stop.requested(); rendered++) {
                if (rendered == warmup) {
                    Poses.direct(engine.world(), CameraDirection.play(cameraPath, cameraPath.startTime(), false));
                }
                engine.update();
                engine.render();
                if (rendered >= warmup) {
                    memory.sample();
                }
                engine.collectFrames(false, r -> keep(r, records));
                if ((rendered + 1) % reportEvery == 0 || System.nanoTime() - lastReport > PROGRESS_EVERY_NS) {
                    System.err.println(rendered < warmup
                            ? String.format("bench: warm-up frame %d of %d", rendered + 1, warmup)
                            : String.format("bench: %d of %d frames recorded", rendered + 1 - warmup, recorded));
                    lastReport = System.nanoTime();
                }
            }
            engine.collectFrames(true, r -> keep(r, records));
            reportLifted(records);
            RunInfo info = new RunInfo(launch.gl.renderer(), launch.gl.version(), launch.gl.mode().toString(),
                    engine.width(), engine.height(), engine.settings().get(EngineSettings.class).seed(),
                    engine.settings().asText(), path.toString(), warmup, profile);
            boolean complete = rendered == total;
            if (!complete && (discardPartial || records.isEmpty())) {
                System.err.printf("bench: stopped by a signal after %d of %d frames; nothing written, %s left as it "
                        + "was%n", records.size(), recorded, out);
                return 0;
            }
            if (!complete) {
                System.err.printf("bench: stopped by a signal after %d of %d frames; writing them as a partial run%n",
                        records.size(), recorded);
            }
            Summary summary = BenchReport.write(info, records, memory.result(), out, complete);
            System.out.println(summary.describe());
            System.out.println("wrote " + out.resolve(BenchReport.FRAMES_CSV) + ", " + out.resolve(BenchReport.SUMMARY_JSON)
                    + ", " + out.resolve(BenchReport.FRAMETIME_PNG));
        }
        return 0;
    }

    /** Says on the standard error how often and how far the director lifted the path's eye out of the ground. */
    private static void reportLifted(List<FrameRecord> records) {
        double[] lifts = records.stream().map(r -> r.counters().get(CameraSystem.LIFTED.name()))
                .filter(m -> m != null).mapToDouble(Double::doubleValue).toArray();
        if (lifts.length > 0) {
            System.err.printf(Locale.ROOT, "bench: the path's eye is below the ground, or nearer it than the near plane "
                    + "(%.1f m), in %d of %d frames: lifted there, by up to %.1f m (column %s of %s)%n",
                    CameraController.MIN_CLEARANCE, lifts.length, records.size(), Arrays.stream(lifts).max().orElse(0),
                    CameraSystem.LIFTED.name(), BenchReport.FRAMES_CSV);
        }
    }

    /**
     * Refuses a run longer than {@link #MAX_FRAMES} in all (warm-up included), counted in {@code long} so that
     * {@code --frames 2147483647 --warmup 1} is a clear message rather than an overflowed count.
     */
    private void checkFrameCount(CameraPath cameraPath) {
        double pathStep = Launch.settings(render).get(EngineSettings.class).step();
        long recorded = frames != null ? frames : (long) Math.floor(cameraPath.duration() / pathStep) + 1;
        if (warmup + recorded > MAX_FRAMES) {
            throw new UserError("--warmup " + warmup + " and " + (frames != null ? "--frames " + frames
                    : recorded + " frames of " + path) + " make " + (warmup + recorded) + " frames: at most "
                    + MAX_FRAMES + " in all (every frame's record is kept in memory for the report)");
        }
    }

    /** Keeps recorded frames, renumbered from 0 with the path time, and drops warm-up frames. */
    private void keep(FrameRecord r, List<FrameRecord> records) {
        int index = r.frame() - warmup;
        if (index >= 0) {
            records.add(new FrameRecord(index, index * step, r.wallMs(), r.cpuMs(), r.systemCpuMs(), r.passGpuMs(),
                    r.triangles(), r.drawCalls(), r.counters()));
        }
    }
}

package org.openworld.engine.bench;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The statistics of one benchmark run, as stored in {@code summary.json} ({@link SummaryJson}) and compared by
 * {@link BenchComparison}. Percentiles are defined in {@link Percentiles}; per-name medians cover only the frames that
 * have that name (see {@link FrameColumns}). Maps keep the system, pass and counter order of the run.
 *
 * @param renderer          GL_RENDERER of the machine that ran it
 * @param glVersion         GL_VERSION
 * @param contextMode       window, headless-egl or headless-x11
 * @param size              render size, "WxH" in pixels
 * @param seed              world seed
 * @param settings          every setting key with its value as text
 * @param path              the camera path file replayed
 * @param warmup            frames rendered before recording
 * @param frames            frames recorded
 * @param complete          whether the run recorded every frame it meant to; false for a run stopped by a signal
 *                          and written with the frames it had ({@code docs/benchmarks.md}); a file written before
 *                          this field existed reads as complete
 * @param profiled          whether the run was profiled ({@code bench --profile}): the GPU finished around every span,
 *                          {@code passGpuMsMedian} holding the spans' wall times and the frames slower than a plain
 *                          run's; a file written before this field existed reads as not profiled
 * @param frameMs           distribution of {@link FrameRecord#frameMs()}, milliseconds
 * @param meanFps           1000 / mean frame time, frames per second
 * @param cpuMs             distribution of whole-frame CPU time, milliseconds
 * @param passGpuMsMedian   median GPU time per system in each pass ({@code pass.system}), milliseconds
 * @param systemCpuMsMedian median CPU time per system, milliseconds
 * @param countersMedian    median of each system counter, in the counter's own unit
 * @param trianglesMedian   median triangles per frame
 * @param drawCallsMedian   median draw calls per frame
 * @param memory            the run's heap, process and GPU memory; null in a file written before it was measured
 */
public record Summary(String renderer, String glVersion, String contextMode, String size, long seed,
                      Map<String, String> settings, String path, int warmup, int frames,
                      Boolean complete, Boolean profiled, FrameTimes frameMs, double meanFps, CpuTimes cpuMs,
                      Map<String, Double> passGpuMsMedian, Map<String, Double> systemCpuMsMedian,
                      Map<String, Double> countersMedian, double trianglesMedian, double drawCallsMedian,
                      MemoryUse memory) {

    /** Frame time statistics, milliseconds. */
    public record FrameTimes(double median, double p95, double p99, double max, double mean) {
    }

    /** Whole-frame CPU time statistics, milliseconds. */
    public record CpuTimes(double median, double p95) {
    }

    /**
     * A file written before a map existed, or by hand, reads as an empty map rather than null, and one written before
     * {@code complete} existed as complete (every run was) and as not profiled (no run was).
     */
    public Summary {
        complete = complete == null || complete;
        profiled = profiled != null && profiled;
        settings = orderedCopy(settings);
        passGpuMsMedian = orderedCopy(passGpuMsMedian);
        systemCpuMsMedian = orderedCopy(systemCpuMsMedian);
        countersMedian = orderedCopy(countersMedian);
    }

    /**
     * Computes the statistics of a run.
     *
     * @param frames the recorded frames, at least one
     * @param memory what the run held in memory ({@link MemoryMeter})
     */
    public static Summary of(RunInfo run, List<FrameRecord> frames, MemoryUse memory) {
        if (frames.isEmpty()) {
            throw new IllegalArgumentException("no frames recorded, nothing to summarise");
        }
        Percentiles frame = Percentiles.of(frames.stream().map(FrameRecord::frameMs).toList());
        Percentiles cpu = Percentiles.of(frames.stream().map(FrameRecord::cpuMs).toList());
        Percentiles triangles = Percentiles.of(frames.stream().map(f -> (double) f.triangles()).toList());
        Percentiles drawCalls = Percentiles.of(frames.stream().map(f -> (double) f.drawCalls()).toList());
        return new Summary(run.renderer(), run.glVersion(), run.contextMode(), run.width() + "x" + run.height(),
                run.seed(), run.settings(), run.path(), run.warmup(), frames.size(), true, run.profiled(),
                new FrameTimes(frame.median(), frame.at(95), frame.at(99), frame.max(), frame.mean()),
                1000.0 / frame.mean(),
                new CpuTimes(cpu.median(), cpu.at(95)),
                FrameColumns.PASS_GPU_MS.medians(frames), FrameColumns.SYSTEM_CPU_MS.medians(frames),
                FrameColumns.COUNTERS.medians(frames), triangles.median(), drawCalls.median(), memory);
    }

    /** This summary, marked complete or partial. */
    public Summary withComplete(boolean isComplete) {
        return new Summary(renderer, glVersion, contextMode, size, seed, settings, path, warmup, frames, isComplete,
                profiled, frameMs, meanFps, cpuMs, passGpuMsMedian, systemCpuMsMedian, countersMedian,
                trianglesMedian, drawCallsMedian, memory);
    }

    /**
     * One paragraph for the command line to print after a run, e.g. "llvmpipe at 1280x720, 600 frames after 60
     * warm-up: frame time median 16.21 ms, p95 18.40 ms, p99 21.03 ms, max 25.10 ms; mean 16.52 ms = 60.5 fps.
     * CPU median 3.10 ms; slowest GPU pass: water 5.20 ms median. Memory: heap peak 412 MiB, RSS peak 1210 MiB, GPU
     * memory not reported by the driver." A profiled run says so at the end.
     */
    public String describe() {
        StringBuilder s = new StringBuilder(String.format(Locale.ROOT,
                "%s%s at %s, %d frames after %d warm-up: frame time median %.2f ms, p95 %.2f ms, p99 %.2f ms, "
                        + "max %.2f ms; mean %.2f ms = %.1f fps. CPU median %.2f ms",
                complete ? "" : "partial run (stopped early): ", renderer, size, frames, warmup, frameMs.median, frameMs.p95, frameMs.p99, frameMs.max, frameMs.mean,
                meanFps, cpuMs.median));
        passGpuMsMedian.entrySet().stream().max(Map.Entry.comparingByValue()).ifPresent(slowest -> s.append(
                String.format(Locale.ROOT, "; slowest GPU pass: %s %.2f ms median", slowest.getKey(),
                        slowest.getValue())));
        s.append('.');
        if (memory != null) {
            s.append(' ').append(memory.describe());
        }
        if (profiled) {
            s.append(" Profiled: the GPU was finished around every span, so the GPU times are the spans' wall times and "
                    + "the frames are slower than a plain run's.");
        }
        return s.toString();
    }

    private static <V> Map<String, V> orderedCopy(Map<String, V> map) {
        return map == null ? Map.of() : Collections.unmodifiableMap(new LinkedHashMap<>(map));
    }
}

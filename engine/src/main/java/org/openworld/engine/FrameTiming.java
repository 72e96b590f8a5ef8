package org.openworld.engine;

import static org.lwjgl.opengl.GL11C.glFinish;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.openworld.engine.bench.FrameRecord;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.Owned;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.FrameThrottle;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.GpuTimers;

/**
 * What a frame cost (docs/benchmarks.md): each system's CPU time, summed over its update and its passes; each span's
 * GPU time from timer queries, labelled {@code pass.system} ({@code shadow0.terrain} for the first of several views,
 * {@code update.particles} for an update that works on the GPU); the frame's CPU time and its wall time from the end
 * of the last frame. GPU times arrive a frame or two late, so each frame's CPU figures wait in a queue until they do
 * and leave as one {@link FrameRecord}.
 *
 * <p>At most two frames are in flight ({@link FrameThrottle}), as with a swap chain: without it a driver that queues
 * work would let the CPU run ahead and the wall times would measure the queue, not the frames.
 *
 * <p><b>Profiling</b> ({@link #profile}): timer queries read near zero on a driver that rasterises at flush (Mesa's
 * llvmpipe). A profiled frame instead finishes the GPU ({@code glFinish}) before and after every span, each update
 * included, and records each span's wall time, so the spans split the frame exactly, on any driver, at the price of
 * serialising CPU and GPU: a profiled frame is slower than a plain one, and its parts are what each costs alone.
 */
final class FrameTiming {

    private final GpuTimers timers;
    private final FrameThrottle throttle;
    /** The systems in resolved order, which is the order of each record's per-system times. */
    private final List<EngineSystem> systems;
    private final Map<String, Double> systemNanos = new LinkedHashMap<>();
    private final Deque<FrameRecord> awaitingGpu = new ArrayDeque<>();
    /** The profiled frame's span times, milliseconds, in the order the spans ran. */
    private final Map<String, Double> profiledMs = new LinkedHashMap<>();
    private final Deque<FrameRecord> profiled = new ArrayDeque<>();
    private boolean profiling;
    private long frameStart;
    private long lastFrameEnd;

    /** Makes the timer queries and the throttle's fences, handing them to {@code owned} (the engine's). */
    FrameTiming(GlContext gl, Owned owned, List<EngineSystem> systems) {
        this.systems = systems;
        timers = owned.own(new GpuTimers(gl));
        throttle = owned.own(new FrameThrottle(gl));
    }

    /** Profiles every frame: each span is timed by finishing the GPU around it. Only before the first frame. */
    void profile() {
        if (lastFrameEnd != 0 || frameStart != 0) {
            throw new IllegalStateException("profiling is chosen before the first frame");
        }
        profiling = true;
    }

    /** Whether every frame is profiled ({@link #profile}). */
    boolean profiling() {
        return profiling;
    }

    /** The frame's rendering starts now. */
    void beginFrame() {
        frameStart = System.nanoTime();
    }

    /**
     * Runs {@code work} for {@code system}, adding its CPU time to the system's, and times it on the GPU as the span
     * {@code gpuSpan} (null: its work issues no GPU commands worth a span).
     */
    void time(String system, String gpuSpan, Runnable work) {
        if (profiling) {
            glFinish();
        }
        long t0 = System.nanoTime();
        if (gpuSpan != null && !profiling) {
            timers.begin(gpuSpan);
        }
        work.run();
        if (gpuSpan != null && !profiling) {
            timers.end();
        }
        long cpuEnd = System.nanoTime();
        systemNanos.merge(system, (double) (cpuEnd - t0), Double::sum);
        if (profiling && gpuSpan != null) {
            glFinish();
            profiledMs.merge(gpuSpan, (System.nanoTime() - t0) / 1e6, Double::sum);
        }
    }

    /**
     * Runs the engine's own part of a pass (binding and clearing its target), timed only when profiling, as the
     * span {@code pass.engine}, so that a profiled frame's spans cover all of it.
     */
    void timeEngine(String span, Runnable work) {
        if (!profiling) {
            work.run();
            return;
        }
        glFinish();
        long t0 = System.nanoTime();
        work.run();
        glFinish();
        profiledMs.merge(span, (System.nanoTime() - t0) / 1e6, Double::sum);
    }

    /** Closes the frame's spans, waits for the frame before the last, and queues the frame's CPU record. */
    void endFrame(long frame, double simTime, DrawStats stats, Counters counters) {
        if (!profiling) {
            timers.endFrame(frame);
        }
        double cpuMs = (System.nanoTime() - frameStart) / 1e6;
        throttle.endFrame();
        long frameEnd = System.nanoTime();
        double wallMs = (frameEnd - (lastFrameEnd != 0 ? lastFrameEnd : frameStart)) / 1e6;
        lastFrameEnd = frameEnd;
        Map<String, Double> systemMs = new LinkedHashMap<>();
        for (EngineSystem s : systems) {
            Double nanos = systemNanos.get(s.spec().name());
            if (nanos != null) {
                systemMs.put(s.spec().name(), nanos / 1e6);
            }
        }
        if (profiling) {
            // no timer queries were made: the record is whole now, its spans' wall times in place of GPU times
            profiled.add(new FrameRecord((int) frame, simTime, wallMs, cpuMs, systemMs, Map.copyOf(profiledMs),
                    stats.triangles(), stats.drawCalls(), counters.snapshot()));
        } else {
            awaitingGpu.add(new FrameRecord((int) frame, simTime, wallMs, cpuMs, systemMs, Map.of(), stats.triangles(),
                    stats.drawCalls(), counters.snapshot()));
        }
        systemNanos.clear();
        profiledMs.clear();
    }

    /**
     * Hands over the records of frames whose GPU timings have arrived, oldest first.
     *
     * @param wait true to wait for the GPU to finish every frame rendered so far
     */
    void collect(boolean wait, Consumer<FrameRecord> sink) {
        while (!profiled.isEmpty()) {
            sink.accept(profiled.pop());
        }
        timers.collect(wait, (frameIndex, gpuMs) -> {
            FrameRecord cpu = awaitingGpu.pop();
            sink.accept(new FrameRecord(cpu.frame(), cpu.simTime(), cpu.wallMs(), cpu.cpuMs(), cpu.systemCpuMs(), gpuMs,
                    cpu.triangles(), cpu.drawCalls(), cpu.counters()));
        });
    }
}

package org.openworld.engine.bench;

import java.util.Map;

/**
 * What one rendered frame cost and drew. Maps keep their insertion order (the resolved system order and the pass
 * order), which is the column order of {@code frames.csv}.
 *
 * @param frame      frame index from 0, warm-up frames excluded
 * @param simTime    simulation time at this frame, seconds
 * @param cpuMs      CPU time of the whole frame, milliseconds
 * @param systemCpuMs CPU time per system (update + render), milliseconds
 * @param passGpuMs  GPU time per pass from timer queries, milliseconds
 * @param triangles  triangles submitted in all passes
 * @param drawCalls  draw calls in all passes
 * @param counters   each system's own counters, e.g. {@code terrain.visible}
 */
public record FrameRecord(int frame, double simTime, double cpuMs, Map<String, Double> systemCpuMs,
                          Map<String, Double> passGpuMs, long triangles, long drawCalls,
                          Map<String, Double> counters) {

    /** The frame time used for statistics: the larger of CPU and GPU time, since either can bound the frame. */
    public double frameMs() {
        double gpu = passGpuMs.values().stream().mapToDouble(Double::doubleValue).sum();
        return Math.max(cpuMs, gpu);
    }
}

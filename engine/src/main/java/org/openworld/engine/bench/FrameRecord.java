package org.openworld.engine.bench;

import java.util.Map;

/**
 * What one rendered frame cost and drew. Maps keep their insertion order (the resolved system order and the pass
 * order), which is the column order of {@code frames.csv}.
 *
 * @param frame      frame index from 0, warm-up frames excluded
 * @param simTime    simulation time at this frame, seconds
 * @param wallMs     wall-clock time from the end of the previous frame to the end of this one, with at most two
 *                   frames in flight (as a swap chain allows): the frame time a viewer sees, milliseconds
 * @param cpuMs      CPU time of the frame's update and render calls, milliseconds
 * @param systemCpuMs CPU time per system (update + render), milliseconds
 * @param passGpuMs  GPU time per system in each pass from timer queries, keyed {@code pass.system} (e.g.
 *                   {@code main.sky}), milliseconds
 * @param triangles  triangles submitted in all passes
 * @param drawCalls  draw calls in all passes
 * @param counters   each system's own counters, e.g. {@code terrain.visible}
 */
public record FrameRecord(int frame, double simTime, double wallMs, double cpuMs, Map<String, Double> systemCpuMs,
                          Map<String, Double> passGpuMs, long triangles, long drawCalls,
                          Map<String, Double> counters) {

    /**
     * The frame time used for statistics: the wall-clock frame interval. CPU and GPU times explain it; they do not
     * replace it, because some drivers (Mesa's llvmpipe among them) rasterise at flush time, outside the timer
     * queries' spans.
     */
    public double frameMs() {
        return wallMs;
    }
}

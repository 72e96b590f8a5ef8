package org.openworld.demo;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import org.openworld.engine.bench.FrameRecord;

/**
 * The last frames' records, for the HUD: the frame-time graph, the frame rate, the latest GPU spans and counters.
 * Records arrive as the GPU finishes their frames ({@code Engine.collectFrames}), a frame or two late.
 */
final class FrameHistory {

    private final int capacity;
    private final Deque<FrameRecord> frames = new ArrayDeque<>();

    /** @param capacity how many frames the graph spans */
    FrameHistory(int capacity) {
        if (capacity < 1) {
            throw new IllegalArgumentException("capacity " + capacity + " must be at least 1");
        }
        this.capacity = capacity;
    }

    void add(FrameRecord record) {
        if (frames.size() == capacity) {
            frames.removeFirst();
        }
        frames.addLast(record);
    }

    /** The newest record, if any arrived. */
    Optional<FrameRecord> latest() {
        return Optional.ofNullable(frames.peekLast());
    }

    /** Frame times of the kept frames, oldest first, milliseconds (the graph's values). */
    float[] frameMs() {
        float[] ms = new float[frames.size()];
        int i = 0;
        for (FrameRecord r : frames) {
            ms[i++] = (float) r.frameMs();
        }
        return ms;
    }

    /** Mean frame time over the kept frames, milliseconds; NaN before any arrived. */
    double meanFrameMs() {
        return frames.stream().mapToDouble(FrameRecord::frameMs).average().orElse(Double.NaN);
    }

    /** Frames per second over the kept frames: their count over their summed time, not a mean of rates. */
    double fps() {
        return 1000 / meanFrameMs();
    }

    /**
     * GPU time per pass: the spans ({@code pass.system}, {@code passN.system} for the N-th view of a pass, or
     * {@code update.system}) summed by the pass's name, in the order the spans came.
     */
    static Map<String, Double> passTotals(Map<String, Double> spans) {
        Map<String, Double> totals = new LinkedHashMap<>();
        spans.forEach((span, ms) -> totals.merge(span.substring(0, span.indexOf('.')).replaceAll("[0-9]+$", ""), ms,
                Double::sum));
        return totals;
    }

    /** Longest frame time kept, milliseconds (the graph's scale); 0 before any arrived. */
    double maxFrameMs() {
        return frames.stream().mapToDouble(FrameRecord::frameMs).max().orElse(0);
    }
}

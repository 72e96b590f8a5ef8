package org.openworld.engine.bench;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;

/**
 * One of the per-name maps of a {@link FrameRecord} (systems, passes or counters), seen across all frames. A system
 * switched on half-way through a run appears only in the later frames, so the names are the union over all frames,
 * in first-seen order, and each name's samples come only from the frames that have it.
 */
enum FrameColumns {
    SYSTEM_CPU_MS(FrameRecord::systemCpuMs),
    PASS_GPU_MS(FrameRecord::passGpuMs),
    COUNTERS(FrameRecord::counters);

    private final Function<FrameRecord, Map<String, Double>> map;

    FrameColumns(Function<FrameRecord, Map<String, Double>> map) {
        this.map = map;
    }

    /** This map of one frame. */
    Map<String, Double> of(FrameRecord frame) {
        return map.apply(frame);
    }

    /** Every name that appears in any frame, in first-seen order. */
    List<String> names(List<FrameRecord> frames) {
        Set<String> names = new LinkedHashSet<>();
        frames.forEach(f -> names.addAll(of(f).keySet()));
        return new ArrayList<>(names);
    }

    /** Each name's median over the frames that have it, in first-seen order. */
    Map<String, Double> medians(List<FrameRecord> frames) {
        Map<String, List<Double>> samples = new LinkedHashMap<>();
        frames.forEach(f -> of(f).forEach((name, v) -> samples.computeIfAbsent(name, n -> new ArrayList<>()).add(v)));
        Map<String, Double> medians = new LinkedHashMap<>();
        samples.forEach((name, values) -> medians.put(name, Percentiles.of(values).median()));
        return medians;
    }
}

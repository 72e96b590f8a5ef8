package org.openworld.engine.bench;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/** Handcrafted runs shared by the benchmark tests: small enough to check every number by hand. */
final class BenchFrames {

    static final RunInfo RUN = new RunInfo("test renderer", "3.3 test", "headless-egl", 640, 360, 42L,
            Map.of("terrain.lod", "4"), "assets/paths/valley.path", 10, false);

    /** Memory as llvmpipe on Linux reports it: heap, RSS and the engine's texture count, no GPU memory. */
    static final MemoryUse MEMORY = new MemoryUse(412.5, 150.0, 1210.0, null, null, null, 160.25, 150.5);

    private BenchFrames() {
    }

    /**
     * Three frames. The "water" system and pass start only in frame 1, the "grass.blades" counter only in frame 2.
     * Frame 0 is CPU-bound (cpu 5 > gpu 3); frames 1 and 2 are GPU-bound; wall time is the larger of each.
     */
    static List<FrameRecord> threeFrames() {
        return List.of(
                new FrameRecord(0, 0.0, 5.0, 5.0, ordered("terrain", 2.0), ordered("terrain", 3.0), 1000, 10,
                        ordered("terrain.visible", 64.0)),
                new FrameRecord(1, 1.0 / 60, 6.0, 4.0, ordered("terrain", 1.5, "water", 0.25),
                        ordered("terrain", 4.0, "water", 2.0), 1200, 12, ordered("terrain.visible", 60.0)),
                new FrameRecord(2, 2.0 / 60, 8.0, 6.0, ordered("terrain", 2.5, "water", 0.75),
                        ordered("terrain", 5.0, "water", 3.0), 1400, 14,
                        ordered("terrain.visible", 56.0, "grass.blades", 1.5)));
    }

    /** A map that keeps the given order, as the engine's maps do. */
    static Map<String, Double> ordered(Object... nameValue) {
        Map<String, Double> map = new LinkedHashMap<>();
        for (int i = 0; i < nameValue.length; i += 2) {
            map.put((String) nameValue[i], (Double) nameValue[i + 1]);
        }
        return map;
    }
}

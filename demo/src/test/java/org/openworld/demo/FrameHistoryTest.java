package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.openworld.engine.bench.FrameRecord;

/** The HUD's numbers: the last frames kept, the frame rate, GPU time per pass. */
class FrameHistoryTest {

    private static FrameRecord frame(int index, double wallMs) {
        return new FrameRecord(index, index / 60.0, wallMs, wallMs / 2, Map.of(), Map.of(), 0, 0, Map.of());
    }

    @Test
    void keepsTheLastFramesOldestFirst() {
        FrameHistory history = new FrameHistory(3);
        assertTrue(history.latest().isEmpty());
        assertTrue(Double.isNaN(history.meanFrameMs()));
        for (int i = 0; i < 5; i++) {
            history.add(frame(i, 10 + i));
        }
        assertArrayEquals(new float[] {12, 13, 14}, history.frameMs());
        assertEquals(4, history.latest().orElseThrow().frame());
        assertEquals(14, history.maxFrameMs());
    }

    @Test
    void theFrameRateIsFramesOverTheirTimeNotAMeanOfRates() {
        FrameHistory history = new FrameHistory(10);
        history.add(frame(0, 10));
        history.add(frame(1, 30));
        // two frames in 40 ms: 50 fps (a mean of 100 and 33 fps would say 67)
        assertEquals(50, history.fps(), 1e-9);
    }

    @Test
    void passTotalsSumTheSystemsAndTheViewsOfAPass() {
        Map<String, Double> spans = new LinkedHashMap<>();
        spans.put("update.particles", 0.5);
        spans.put("shadow0.terrain", 1.0);
        spans.put("shadow1.terrain", 2.0);
        spans.put("shadow1.culling", 0.25);
        spans.put("main.sky", 3.0);
        spans.put("main.terrain", 4.0);

        Map<String, Double> totals = FrameHistory.passTotals(spans);

        assertEquals(List.of("update", "shadow", "main"), List.copyOf(totals.keySet()));
        assertEquals(3.25, totals.get("shadow"));
        assertEquals(7.0, totals.get("main"));
    }
}

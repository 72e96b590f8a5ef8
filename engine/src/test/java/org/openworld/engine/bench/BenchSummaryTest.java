package org.openworld.engine.bench;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class BenchSummaryTest {

    private static final double EPS = 1e-9;

    @TempDir
    Path dir;

    @Test
    void statisticsOfTheHandcraftedRun() {
        Summary s = Summary.of(BenchFrames.RUN, BenchFrames.threeFrames());

        // frame ms per frame: max(5, 3) = 5, max(4, 6) = 6, max(6, 8) = 8
        assertEquals(3, s.frames());
        assertEquals(6.0, s.frameMs().median(), EPS);
        assertEquals(7.8, s.frameMs().p95(), EPS);   // position 1.9: 6 + 0.9 * (8 - 6)
        assertEquals(7.96, s.frameMs().p99(), EPS);  // position 1.98
        assertEquals(8.0, s.frameMs().max(), EPS);
        assertEquals(19.0 / 3, s.frameMs().mean(), EPS);
        assertEquals(1000 / (19.0 / 3), s.meanFps(), EPS);
        assertEquals(5.0, s.cpuMs().median(), EPS);
        assertEquals(5.9, s.cpuMs().p95(), EPS);
        // water exists only in frames 1 and 2, so its median is over those two
        assertEquals(Map.of("terrain", 4.0, "water", 2.5), s.passGpuMsMedian());
        assertEquals(Map.of("terrain", 2.0, "water", 0.5), s.systemCpuMsMedian());
        assertEquals(Map.of("terrain.visible", 60.0, "grass.blades", 1.5), s.countersMedian());
        assertEquals(1200.0, s.trianglesMedian(), EPS);
        assertEquals(12.0, s.drawCallsMedian(), EPS);
        assertEquals("640x360", s.size());
    }

    @Test
    void writtenAndReadBackUnchangedInOrder() throws IOException {
        Summary written = BenchReport.write(BenchFrames.RUN, BenchFrames.threeFrames(), dir.resolve("run"), true);
        Path json = dir.resolve("run").resolve(BenchReport.SUMMARY_JSON);

        Summary read = SummaryJson.read(json);
        assertEquals(written, read);
        assertEquals(6.0, read.frameMs().median(), EPS);
        assertEquals(List.of("terrain.visible", "grass.blades"), List.copyOf(read.countersMedian().keySet()));

        String text = Files.readString(json);
        for (String field : List.of("\"renderer\"", "\"glVersion\"", "\"contextMode\"", "\"size\": \"640x360\"",
                "\"seed\": 42", "\"settings\"", "\"path\"", "\"warmup\": 10", "\"frames\": 3", "\"complete\": true", "\"frameMs\"",
                "\"p99\"", "\"meanFps\"", "\"cpuMs\"", "\"passGpuMsMedian\"", "\"systemCpuMsMedian\"",
                "\"countersMedian\"", "\"trianglesMedian\"", "\"drawCallsMedian\"")) {
            assertTrue(text.contains(field), () -> field + " missing in\n" + text);
        }
    }

    @Test
    void aPartialRunSaysSoInTheFileAndTheDescription() throws IOException {
        Summary written = BenchReport.write(BenchFrames.RUN, BenchFrames.threeFrames(), dir.resolve("run"), false);
        Path json = dir.resolve("run").resolve(BenchReport.SUMMARY_JSON);
        assertTrue(Files.readString(json).contains("\"complete\": false"), Files.readString(json));
        Summary read = SummaryJson.read(json);
        assertFalse(read.complete());
        assertEquals(written, read);
        assertTrue(read.describe().startsWith("partial run (stopped early): test renderer at 640x360, 3 frames"),
                read.describe());
    }

    @Test
    void aSummaryWrittenBeforeCompleteExistedReadsAsComplete() throws IOException {
        Path json = dir.resolve(BenchReport.SUMMARY_JSON);
        SummaryJson.write(Summary.of(BenchFrames.RUN, BenchFrames.threeFrames()), json);
        Files.writeString(json, Files.readString(json).replaceAll("\\s*\"complete\": true,", ""));
        assertFalse(Files.readString(json).contains("complete"));
        assertTrue(SummaryJson.read(json).complete());
    }

    @Test
    void describeNamesTheNumbersTheCommandLinePrints() {
        String text = Summary.of(BenchFrames.RUN, BenchFrames.threeFrames()).describe();
        assertTrue(text.startsWith("test renderer at 640x360, 3 frames after 10 warm-up"), text);
        assertTrue(text.contains("median 6.00 ms, p95 7.80 ms, p99 7.96 ms"), text);
        assertTrue(text.contains("157.9 fps"), text);
        assertTrue(text.contains("slowest GPU pass: terrain 4.00 ms median"), text);
    }

    @Test
    void noFramesIsAnError() {
        assertThrows(IllegalArgumentException.class, () -> Summary.of(BenchFrames.RUN, List.of()));
    }
}

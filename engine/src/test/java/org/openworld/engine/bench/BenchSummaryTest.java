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
        Summary s = Summary.of(BenchFrames.RUN, BenchFrames.threeFrames(), BenchFrames.MEMORY);

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
        Summary written = BenchReport.write(BenchFrames.RUN, BenchFrames.threeFrames(), BenchFrames.MEMORY, dir.resolve("run"), true);
        Path json = dir.resolve("run").resolve(BenchReport.SUMMARY_JSON);

        Summary read = SummaryJson.read(json);
        assertEquals(written, read);
        assertEquals(6.0, read.frameMs().median(), EPS);
        assertEquals(List.of("terrain.visible", "grass.blades"), List.copyOf(read.countersMedian().keySet()));

        String text = Files.readString(json);
        for (String field : List.of("\"renderer\"", "\"glVersion\"", "\"contextMode\"", "\"size\": \"640x360\"",
                "\"seed\": 42", "\"settings\"", "\"path\"", "\"warmup\": 10", "\"frames\": 3", "\"complete\": true", "\"frameMs\"",
                "\"p99\"", "\"meanFps\"", "\"cpuMs\"", "\"passGpuMsMedian\"", "\"systemCpuMsMedian\"",
                "\"countersMedian\"", "\"trianglesMedian\"", "\"drawCallsMedian\"", "\"profiled\": false",
                "\"heapPeakMib\": 412.5", "\"heapAfterGcPeakMib\": 150.0", "\"rssPeakMib\": 1210.0",
                "\"gpuUsedPeakMib\": null")) {
            assertTrue(text.contains(field), () -> field + " missing in\n" + text);
        }
    }

    @Test
    void aPartialRunSaysSoInTheFileAndTheDescription() throws IOException {
        Summary written = BenchReport.write(BenchFrames.RUN, BenchFrames.threeFrames(), BenchFrames.MEMORY, dir.resolve("run"), false);
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
        SummaryJson.write(Summary.of(BenchFrames.RUN, BenchFrames.threeFrames(), BenchFrames.MEMORY), json);
        Files.writeString(json, Files.readString(json).replaceAll("\\s*\"complete\": true,", ""));
        assertFalse(Files.readString(json).contains("complete"));
        assertTrue(SummaryJson.read(json).complete());
    }

    @Test
    void aSummaryWrittenBeforeProfilingAndMemoryExistedReadsAsPlainWithoutMemory() throws IOException {
        Path json = dir.resolve(BenchReport.SUMMARY_JSON);
        SummaryJson.write(Summary.of(BenchFrames.RUN, BenchFrames.threeFrames(), BenchFrames.MEMORY), json);
        String old = Files.readString(json).replaceAll("\\s*\"profiled\": false,", "")
                .replaceAll(",\\s*\"memory\": \\{[^}]*\\}", "");
        Files.writeString(json, old);
        assertFalse(old.contains("profiled") || old.contains("memory") || old.contains("Mib"), old);
        Summary read = SummaryJson.read(json);
        assertFalse(read.profiled());
        assertEquals(null, read.memory());
        assertFalse(read.describe().contains("Memory"), read.describe());
    }

    @Test
    void aSummaryWrittenBeforeTexturesAndTheHeapAfterCollectionsWereMeasuredReadsThemAsNull() throws IOException {
        Path json = dir.resolve(BenchReport.SUMMARY_JSON);
        SummaryJson.write(Summary.of(BenchFrames.RUN, BenchFrames.threeFrames(), BenchFrames.MEMORY), json);
        String old = Files.readString(json).replaceAll(",\\s*\"texture\\w+Mib\": [0-9.]+", "")
                .replaceAll("\"heapAfterGcPeakMib\": [0-9.]+,\\s*", "");
        Files.writeString(json, old);
        assertFalse(old.contains("texture") || old.contains("AfterGc"), old);
        MemoryUse read = SummaryJson.read(json).memory();
        assertEquals(412.5, read.heapPeakMib());
        assertEquals(null, read.heapAfterGcPeakMib());
        assertEquals(null, read.texturePeakMib());
        assertEquals(null, read.textureEndMib());
        assertFalse(read.describe().contains("textures"), read.describe());
    }

    @Test
    void aProfiledRunWithGpuMemoryIsReadBackAndDescribed() throws IOException {
        RunInfo profiled = new RunInfo("NVIDIA H100", "4.6", "headless-egl", 640, 360, 42L, Map.of(), "valley.path", 10,
                true);
        MemoryUse memory = new MemoryUse(300.0, 120.0, 900.0, 81920.0, 2048.0, 79872.0, 512.0, 500.0);
        Path run = dir.resolve("run");
        Summary written = BenchReport.write(profiled, BenchFrames.threeFrames(), memory, run, true);
        Summary read = SummaryJson.read(run.resolve(BenchReport.SUMMARY_JSON));
        assertEquals(written, read);
        assertTrue(read.profiled());
        assertEquals(memory, read.memory());
        assertTrue(read.describe().contains("Memory: heap peak 300 MiB (after a collection 120 MiB), RSS peak 900 MiB, textures peak 512 MiB, GPU "
                + "used peak 2048 MiB of 81920 MiB."), read.describe());
        assertTrue(read.describe().contains("Profiled:"), read.describe());
    }

    @Test
    void describeNamesTheNumbersTheCommandLinePrints() {
        String text = Summary.of(BenchFrames.RUN, BenchFrames.threeFrames(), BenchFrames.MEMORY).describe();
        assertTrue(text.startsWith("test renderer at 640x360, 3 frames after 10 warm-up"), text);
        assertTrue(text.contains("median 6.00 ms, p95 7.80 ms, p99 7.96 ms"), text);
        assertTrue(text.contains("157.9 fps"), text);
        assertTrue(text.contains("slowest GPU pass: terrain 4.00 ms median"), text);
        assertTrue(text.contains("Memory: heap peak 413 MiB (after a collection 150 MiB), RSS peak 1210 MiB, textures "
                + "peak 160 MiB, GPU memory not reported by the driver."), text);
        assertFalse(text.contains("Profiled"), text);
    }

    @Test
    void noFramesIsAnError() {
        assertThrows(IllegalArgumentException.class, () -> Summary.of(BenchFrames.RUN, List.of(), BenchFrames.MEMORY));
    }
}

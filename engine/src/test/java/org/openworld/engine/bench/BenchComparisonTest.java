package org.openworld.engine.bench;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.OptionalDouble;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class BenchComparisonTest {

    private static final double EPS = 1e-9;

    /** Run A: water on, grass counter at 0. */
    private static final Summary A = new Summary("test renderer", "3.3", "headless-egl", "640x360", 42L,
            Map.of("water.method", "fft"), "valley.path", 10, 100, true, false,
            new Summary.FrameTimes(10, 12, 15, 20, 10.5), 1000 / 10.5, new Summary.CpuTimes(4, 5),
            BenchFrames.ordered("terrain", 6.0, "water", 2.0), BenchFrames.ordered("terrain", 3.0),
            BenchFrames.ordered("terrain.visible", 100.0, "grass.blades", 0.0), 1_000_000, 100,
            new MemoryUse(400.0, 140.0, 1000.0, 8192.0, 2048.0, 6144.0, 200.0, 180.0));

    /** Run B: water off, a sky pass added, faster terrain. */
    private static final Summary B = new Summary("test renderer", "3.3", "headless-egl", "640x360", 42L,
            Map.of("water.method", "off"), "valley.path", 10, 100, true, false,
            new Summary.FrameTimes(8, 9, 12, 30, 8.4), 1000 / 8.4, new Summary.CpuTimes(5, 6),
            BenchFrames.ordered("terrain", 3.0, "sky", 1.0), BenchFrames.ordered("terrain", 1.5),
            BenchFrames.ordered("terrain.visible", 80.0, "grass.blades", 5.0), 500_000, 150,
            new MemoryUse(300.0, null, 1500.0, null, null, null, 250.0, 240.0));

    @TempDir
    Path dir;

    @Test
    void ratiosAreBOverA() {
        Map<String, BenchComparison.Row> rows = byMetric(new BenchComparison(A, B).rows());
        assertRatio(0.8, rows.get("frame ms median"));
        assertRatio(0.75, rows.get("frame ms p95"));
        assertRatio(0.8, rows.get("frame ms p99"));
        assertRatio(1.5, rows.get("frame ms max"));
        assertRatio(1.25, rows.get("mean fps"));
        assertRatio(1.25, rows.get("CPU ms median"));
        assertRatio(0.5, rows.get("GPU ms median, pass terrain"));
        assertRatio(0.5, rows.get("CPU ms median, system terrain"));
        assertRatio(0.8, rows.get("counter median, terrain.visible"));
        assertRatio(0.5, rows.get("triangles median"));
        assertRatio(1.5, rows.get("draw calls median"));
        assertRatio(0.75, rows.get("heap peak MiB"));
        assertRatio(1.5, rows.get("RSS peak MiB"));
        assertRatio(1.25, rows.get("texture peak MiB"));
    }

    @Test
    void gpuMemoryOneDriverDoesNotReportHasNoRatio() {
        Map<String, BenchComparison.Row> rows = byMetric(new BenchComparison(A, B).rows());
        assertEquals(OptionalDouble.of(2048.0), rows.get("GPU memory used peak MiB").a());
        assertEquals(OptionalDouble.empty(), rows.get("GPU memory used peak MiB").b());
        assertEquals(OptionalDouble.empty(), rows.get("GPU memory used peak MiB").ratio());
    }

    @Test
    void aSummaryWithoutMemoryComparesWithDashes() {
        Summary old = new Summary("test renderer", "3.3", "headless-egl", "640x360", 42L, Map.of("water.method", "fft"),
                "valley.path", 10, 100, true, false, A.frameMs(), A.meanFps(), A.cpuMs(), A.passGpuMsMedian(),
                A.systemCpuMsMedian(), A.countersMedian(), A.trianglesMedian(), A.drawCallsMedian(), null);
        BenchComparison.Row heap = byMetric(new BenchComparison(old, A).rows()).get("heap peak MiB");
        assertEquals(OptionalDouble.empty(), heap.a());
        assertEquals(OptionalDouble.of(400.0), heap.b());
        assertTrue(lineOf(new BenchComparison(old, A).table(), "heap peak MiB").matches(".*—\\s+400\\.000\\s+—"));
    }

    @Test
    void comparingAProfiledWithAPlainRunWarns() {
        Summary profiled = new Summary(B.renderer(), B.glVersion(), B.contextMode(), B.size(), B.seed(), A.settings(),
                B.path(), B.warmup(), B.frames(), true, true, B.frameMs(), B.meanFps(), B.cpuMs(), B.passGpuMsMedian(),
                B.systemCpuMsMedian(), B.countersMedian(), B.trianglesMedian(), B.drawCallsMedian(), B.memory());
        BenchComparison comparison = new BenchComparison(A, profiled);
        assertEquals(List.of("profiled"), comparison.mismatches());
        String table = comparison.table();
        assertTrue(table.contains("B: test renderer, 640x360, valley.path, 100 frames after 10 warm-up, profiled\n"),
                table);
        assertTrue(table.contains("note: only B is profiled"), table);
        assertFalse(new BenchComparison(A, B).table().contains("profiled"));
    }

    @Test
    void noRatioWhereASideLacksTheMetricOrAIsZero() {
        Map<String, BenchComparison.Row> rows = byMetric(new BenchComparison(A, B).rows());
        BenchComparison.Row water = rows.get("GPU ms median, pass water");
        assertEquals(OptionalDouble.of(2.0), water.a());
        assertEquals(OptionalDouble.empty(), water.b());
        assertEquals(OptionalDouble.empty(), water.ratio());
        assertEquals(OptionalDouble.empty(), rows.get("GPU ms median, pass sky").a());
        assertEquals(OptionalDouble.empty(), rows.get("GPU ms median, pass sky").ratio());
        assertEquals(OptionalDouble.empty(), rows.get("counter median, grass.blades").ratio());
    }

    @Test
    void passesAreTheUnionInAsOrderThenBs() {
        List<String> metrics = new BenchComparison(A, B).rows().stream().map(BenchComparison.Row::metric).toList();
        int terrain = metrics.indexOf("GPU ms median, pass terrain");
        assertEquals(List.of("GPU ms median, pass terrain", "GPU ms median, pass water", "GPU ms median, pass sky"),
                metrics.subList(terrain, terrain + 3));
    }

    @Test
    void tablePrintsRatiosDashesAndWarnsAboutDifferentSettings() {
        BenchComparison comparison = new BenchComparison(A, B);
        assertEquals(List.of("settings"), comparison.mismatches());

        String table = comparison.table();
        assertTrue(table.contains("note: A and B differ in settings"), table);
        assertTrue(lineOf(table, "frame ms median ").matches("frame ms median\\s+10\\.000\\s+8\\.000\\s+0\\.800"),
                table);
        assertTrue(lineOf(table, "GPU ms median, pass water").matches(".*2\\.000\\s+—\\s+—"), table);
        assertTrue(lineOf(table, "triangles median").matches(".*1000000\\s+500000\\s+0\\.500"), table);
    }

    @Test
    void tableSaysWhichRunIsPartial() {
        String table = new BenchComparison(A, B.withComplete(false)).table();
        assertTrue(table.contains("B: test renderer, 640x360, valley.path, 100 frames after 10 warm-up, partial"),
                table);
        assertTrue(table.contains("A: test renderer, 640x360, valley.path, 100 frames after 10 warm-up\n"), table);
        assertTrue(table.contains("note: a partial run"), table);
        assertFalse(new BenchComparison(A, B).table().contains("partial"));
    }

    @Test
    void readsTwoSummaryFiles() throws IOException {
        Path a = dir.resolve("a.json");
        Path b = dir.resolve("b.json");
        SummaryJson.write(A, a);
        SummaryJson.write(B, b);
        assertRatio(0.8, byMetric(BenchComparison.read(a, b).rows()).get("frame ms median"));
    }

    @Test
    void malformedOrMissingSummaryNamesTheFile() throws IOException {
        Path good = dir.resolve("good.json");
        SummaryJson.write(A, good);

        Path broken = dir.resolve("broken.json");
        Files.writeString(broken, "{ \"renderer\": \"x\", ");
        assertNamesFile(broken, assertThrows(SummaryFileException.class, () -> BenchComparison.read(good, broken)));

        Path notASummary = dir.resolve("other.json");
        Files.writeString(notASummary, "{ \"name\": \"something else\" }");
        assertNamesFile(notASummary,
                assertThrows(SummaryFileException.class, () -> BenchComparison.read(notASummary, good)));

        Path empty = dir.resolve("empty.json");
        Files.writeString(empty, "");
        assertNamesFile(empty, assertThrows(SummaryFileException.class, () -> SummaryJson.read(empty)));

        Path missing = dir.resolve("missing").resolve("summary.json");
        assertNamesFile(missing, assertThrows(SummaryFileException.class, () -> BenchComparison.read(good, missing)));
    }

    private static void assertNamesFile(Path file, SummaryFileException e) {
        assertEquals(file, e.file());
        assertTrue(e.getMessage().contains(file.toString()), e.getMessage());
    }

    private static void assertRatio(double expected, BenchComparison.Row row) {
        assertEquals(expected, row.ratio().orElseThrow(), EPS, row.metric());
    }

    private static Map<String, BenchComparison.Row> byMetric(List<BenchComparison.Row> rows) {
        Map<String, BenchComparison.Row> map = new java.util.LinkedHashMap<>();
        rows.forEach(r -> map.put(r.metric(), r));
        return map;
    }

    private static String lineOf(String table, String start) {
        return table.lines().filter(l -> l.startsWith(start)).findFirst().orElseThrow(() -> new AssertionError(
                "no line starting with '" + start + "' in\n" + table));
    }
}

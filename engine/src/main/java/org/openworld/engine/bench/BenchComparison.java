package org.openworld.engine.bench;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.OptionalDouble;
import java.util.Set;
import java.util.function.Function;
import java.util.function.ToDoubleFunction;

/**
 * Two benchmark summaries side by side, metric by metric, with the ratio B/A: for times below 1 means B is faster,
 * for fps above 1 does. Backs {@code openworld bench --compare A/summary.json B/summary.json}.
 *
 * <p>A ratio only means something if both runs rendered the same thing on the same machine, so {@link #table()} warns
 * when the renderer, size, camera path, seed, settings or profiling differ ({@link #mismatches()}), and says when a
 * run is partial ({@link Summary#complete()}) or profiled ({@link Summary#profiled()}).
 */
public final class BenchComparison {

    /** Printed where a value or ratio does not exist: a metric one run lacks, or a ratio over a zero A. */
    public static final String MISSING = "—";

    /**
     * One compared metric.
     *
     * @param metric what was measured, with its unit, e.g. "frame ms p95"
     * @param a      the value in run A, empty if A lacks the metric
     * @param b      the value in run B, empty if B lacks the metric
     */
    public record Row(String metric, OptionalDouble a, OptionalDouble b) {

        /** B / A, empty if either side lacks the metric or A is 0. */
        public OptionalDouble ratio() {
            if (a.isEmpty() || b.isEmpty() || a.getAsDouble() == 0) {
                return OptionalDouble.empty();
            }
            return OptionalDouble.of(b.getAsDouble() / a.getAsDouble());
        }
    }

    /** Values at or above this magnitude are counts (triangles, draw calls) and print without a fraction. */
    private static final double WHOLE_NUMBER_FROM = 1000;

    private final Summary a;
    private final Summary b;

    public BenchComparison(Summary a, Summary b) {
        this.a = a;
        this.b = b;
    }

    /**
     * Reads and compares two {@code summary.json} files.
     *
     * @throws SummaryFileException naming the file that is missing or malformed
     */
    public static BenchComparison read(Path a, Path b) {
        return new BenchComparison(SummaryJson.read(a), SummaryJson.read(b));
    }

    /**
     * Every metric of either run: frame time, fps, CPU time, then per pass, per system and per counter (the union
     * of both runs, A's order first), then triangles and draw calls, then memory (a value a run lacks: its file
     * predates it, or the machine does not report it).
     */
    public List<Row> rows() {
        List<Row> rows = new ArrayList<>();
        rows.add(both("frame ms median", s -> s.frameMs().median()));
        rows.add(both("frame ms p95", s -> s.frameMs().p95()));
        rows.add(both("frame ms p99", s -> s.frameMs().p99()));
        rows.add(both("frame ms max", s -> s.frameMs().max()));
        rows.add(both("mean fps", Summary::meanFps));
        rows.add(both("CPU ms median", s -> s.cpuMs().median()));
        rows.add(both("CPU ms p95", s -> s.cpuMs().p95()));
        addNamed(rows, "GPU ms median, pass ", Summary::passGpuMsMedian);
        addNamed(rows, "CPU ms median, system ", Summary::systemCpuMsMedian);
        addNamed(rows, "counter median, ", Summary::countersMedian);
        rows.add(both("triangles median", Summary::trianglesMedian));
        rows.add(both("draw calls median", Summary::drawCallsMedian));
        rows.add(memory("heap peak MiB", MemoryUse::heapPeakMib));
        rows.add(memory("heap after GC peak MiB", MemoryUse::heapAfterGcPeakMib));
        rows.add(memory("RSS peak MiB", MemoryUse::rssPeakMib));
        rows.add(memory("texture peak MiB", MemoryUse::texturePeakMib));
        rows.add(memory("GPU memory used peak MiB", MemoryUse::gpuUsedPeakMib));
        rows.add(memory("GPU memory free low MiB", MemoryUse::gpuFreeLowMib));
        return rows;
    }

    /** The run inputs that differ between A and B, by summary field name; empty for a fair comparison. */
    public List<String> mismatches() {
        List<String> differ = new ArrayList<>();
        if (!Objects.equals(a.renderer(), b.renderer())) differ.add("renderer");
        if (!Objects.equals(a.size(), b.size())) differ.add("size");
        if (!Objects.equals(a.path(), b.path())) differ.add("path");
        if (a.seed() != b.seed()) differ.add("seed");
        if (!a.settings().equals(b.settings())) differ.add("settings");
        if (!a.profiled().equals(b.profiled())) differ.add("profiled");
        return differ;
    }

    /** A plain-text table: what A and B were, a warning if they differ in more than the code, then the rows. */
    public String table() {
        StringBuilder s = new StringBuilder();
        s.append(describeRun("A", a)).append(describeRun("B", b));
        if (!a.complete() || !b.complete()) {
            s.append("note: a partial run (stopped early) covers only the start of its camera path\n");
        }
        if (!a.profiled().equals(b.profiled())) {
            s.append("note: only ").append(a.profiled() ? "A" : "B").append(" is profiled: its frames are slower (the "
                    + "GPU finished around every span) and its GPU times are wall times, not timer queries\n");
        }
        List<String> differ = mismatches();
        if (!differ.isEmpty()) {
            s.append("note: A and B differ in ").append(String.join(", ", differ))
                    .append("; the ratios mix that difference into the comparison\n");
        }
        s.append('\n');

        List<String[]> cells = new ArrayList<>();
        cells.add(new String[] {"metric", "A", "B", "B/A"});
        for (Row row : rows()) {
            cells.add(new String[] {row.metric(), format(row.a()), format(row.b()), format(row.ratio())});
        }
        int[] width = new int[4];
        cells.forEach(r -> { for (int c = 0; c < 4; c++) width[c] = Math.max(width[c], r[c].length()); });
        for (String[] r : cells) {
            s.append(String.format(Locale.ROOT, "%-" + width[0] + "s  %" + width[1] + "s  %" + width[2] + "s  %"
                    + width[3] + "s%n", r[0], r[1], r[2], r[3]));
        }
        return s.toString();
    }

    private Row both(String metric, ToDoubleFunction<Summary> value) {
        return new Row(metric, OptionalDouble.of(value.applyAsDouble(a)),
                OptionalDouble.of(value.applyAsDouble(b)));
    }

    /** A memory metric, empty on a side whose file has no memory or whose machine did not report this value. */
    private Row memory(String metric, Function<MemoryUse, Double> value) {
        return new Row(metric, memoryOf(a, value), memoryOf(b, value));
    }

    private static OptionalDouble memoryOf(Summary s, Function<MemoryUse, Double> value) {
        Double v = s.memory() == null ? null : value.apply(s.memory());
        return v == null ? OptionalDouble.empty() : OptionalDouble.of(v);
    }

    private void addNamed(List<Row> rows, String prefix, Function<Summary, Map<String, Double>> map) {
        Set<String> names = new LinkedHashSet<>(map.apply(a).keySet());
        names.addAll(map.apply(b).keySet());
        for (String name : names) {
            rows.add(new Row(prefix + name, valueOf(map.apply(a), name), valueOf(map.apply(b), name)));
        }
    }

    private static OptionalDouble valueOf(Map<String, Double> map, String name) {
        Double v = map.get(name);
        return v == null ? OptionalDouble.empty() : OptionalDouble.of(v);
    }

    private static String describeRun(String label, Summary s) {
        return String.format(Locale.ROOT, "%s: %s, %s, %s, %d frames after %d warm-up%s%s%n", label, s.renderer(),
                s.size(), s.path(), s.frames(), s.warmup(), s.complete() ? "" : ", partial",
                s.profiled() ? ", profiled" : "");
    }

    private static String format(OptionalDouble value) {
        if (value.isEmpty()) {
            return MISSING;
        }
        double v = value.getAsDouble();
        return String.format(Locale.ROOT, Math.abs(v) >= WHOLE_NUMBER_FROM ? "%.0f" : "%.3f", v);
    }
}

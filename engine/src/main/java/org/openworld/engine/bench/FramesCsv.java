package org.openworld.engine.bench;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Writes {@code frames.csv}: one row per recorded frame, for spreadsheets and plotting scripts.
 *
 * <p>Columns: {@code frame,sim_time_s,cpu_ms,frame_ms}, then {@code cpu_ms.<system>} per system,
 * {@code gpu_ms.<pass>.<system>} per system in each pass, {@code triangles,draw_calls}, then one column per counter under its own name.
 * The named columns are the union over all frames in first-seen order ({@link FrameColumns}); a frame without a
 * value leaves its cell empty. Numbers use '.' as the decimal separator whatever the machine's locale
 * ({@link Locale#ROOT}), so a German or French machine writes the same file.
 */
public final class FramesCsv {

    /** Digits after the point for times: 0.1 µs resolution, finer than any timer we read. */
    private static final String TIME_FORMAT = "%.4f";

    private FramesCsv() {
    }

    /** Writes all frames to {@code file}, replacing it. */
    public static void write(List<FrameRecord> frames, Path file) throws IOException {
        List<String> systems = FrameColumns.SYSTEM_CPU_MS.names(frames);
        List<String> passes = FrameColumns.PASS_GPU_MS.names(frames);
        List<String> counters = FrameColumns.COUNTERS.names(frames);
        try (Writer out = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
            List<String> header = new ArrayList<>(List.of("frame", "sim_time_s", "cpu_ms", "frame_ms"));
            systems.forEach(s -> header.add("cpu_ms." + s));
            passes.forEach(p -> header.add("gpu_ms." + p));
            header.addAll(List.of("triangles", "draw_calls"));
            header.addAll(counters);
            writeRow(out, header.stream().map(FramesCsv::quoted).toList());

            for (FrameRecord f : frames) {
                List<String> row = new ArrayList<>();
                row.add(Integer.toString(f.frame()));
                row.add(time(f.simTime()));
                row.add(time(f.cpuMs()));
                row.add(time(f.frameMs()));
                systems.forEach(s -> row.add(optional(f.systemCpuMs(), s, true)));
                passes.forEach(p -> row.add(optional(f.passGpuMs(), p, true)));
                row.add(Long.toString(f.triangles()));
                row.add(Long.toString(f.drawCalls()));
                counters.forEach(c -> row.add(optional(f.counters(), c, false)));
                writeRow(out, row);
            }
        }
    }

    private static void writeRow(Writer out, List<String> cells) throws IOException {
        out.write(String.join(",", cells));
        out.write('\n');
    }

    private static String optional(Map<String, Double> values, String name, boolean isTime) {
        Double v = values.get(name);
        if (v == null) {
            return "";
        }
        return isTime ? time(v) : counter(v);
    }

    private static String time(double value) {
        return String.format(Locale.ROOT, TIME_FORMAT, value);
    }

    /** Counters are mostly counts: whole values print without a fraction, others like a time. */
    private static String counter(double value) {
        return value == (long) value ? Long.toString((long) value) : time(value);
    }

    /** RFC 4180 quoting, needed only if a system, pass or counter name holds a comma, quote or line break. */
    private static String quoted(String cell) {
        if (cell.chars().noneMatch(c -> c == ',' || c == '"' || c == '\n' || c == '\r')) {
            return cell;
        }
        return '"' + cell.replace("\"", "\"\"") + '"';
    }
}

package org.openworld.engine.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * Writes the three files of one benchmark run into an output folder: {@value #FRAMES_CSV} (every frame,
 * {@link FramesCsv}), {@value #SUMMARY_JSON} (the statistics, {@link SummaryJson}) and {@value #FRAMETIME_PNG} (the
 * chart, {@link FrameTimeChart}). {@code docs/benchmarks.md} describes every column and field.
 */
public final class BenchReport {

    public static final String FRAMES_CSV = "frames.csv";
    public static final String SUMMARY_JSON = "summary.json";
    public static final String FRAMETIME_PNG = "frametime.png";

    private BenchReport() {
    }

    /**
     * Writes all three files, creating {@code outDir} if needed and replacing files of an earlier run.
     *
     * @param frames the recorded frames, at least one
     * @return the summary, whose {@link Summary#describe()} the command line prints
     */
    public static Summary write(RunInfo run, List<FrameRecord> frames, Path outDir) throws IOException {
        Summary summary = Summary.of(run, frames);
        Files.createDirectories(outDir);
        FramesCsv.write(frames, outDir.resolve(FRAMES_CSV));
        SummaryJson.write(summary, outDir.resolve(SUMMARY_JSON));
        FrameTimeChart.write(run, frames, outDir.resolve(FRAMETIME_PNG));
        return summary;
    }
}

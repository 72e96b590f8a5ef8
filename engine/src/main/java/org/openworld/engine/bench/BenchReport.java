package org.openworld.engine.bench;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import org.openworld.engine.files.AtomicFiles;

/**
 * Writes the three files of one benchmark run into an output folder: {@value #FRAMES_CSV} (every frame,
 * {@link FramesCsv}), {@value #SUMMARY_JSON} (the statistics, {@link SummaryJson}) and {@value #FRAMETIME_PNG} (the
 * chart, {@link FrameTimeChart}). {@code docs/benchmarks.md} describes every column and field.
 *
 * <p>The three are written together into a new folder that then replaces the old one
 * ({@link AtomicFiles#replaceFolder}: two renames), so a reader finds the earlier run or this one, never a mix; a
 * crash between the two renames leaves the earlier run whole at {@link AtomicFiles#aside} and no output folder.
 */
public final class BenchReport {

    public static final String FRAMES_CSV = "frames.csv";
    public static final String SUMMARY_JSON = "summary.json";
    public static final String FRAMETIME_PNG = "frametime.png";
    /** The three files, all a run's folder holds. */
    public static final Set<String> FILES = Set.of(FRAMES_CSV, SUMMARY_JSON, FRAMETIME_PNG);

    private BenchReport() {
    }

    /**
     * Writes all three files as a new {@code outDir}, which replaces the old one and everything in it.
     *
     * @param frames   the recorded frames, at least one
     * @param memory   what the run held in memory ({@link MemoryMeter})
     * @param complete whether the run recorded every frame it meant to ({@link Summary#complete()})
     * @return the summary, whose {@link Summary#describe()} the command line prints
     */
    public static Summary write(RunInfo run, List<FrameRecord> frames, MemoryUse memory, Path outDir,
                                boolean complete)
            throws IOException {
        Summary summary = Summary.of(run, frames, memory).withComplete(complete);
        AtomicFiles.replaceFolder(outDir, dir -> {
            AtomicFiles.writeInto(dir.resolve(FRAMES_CSV), outDir.resolve(FRAMES_CSV),
                    file -> FramesCsv.write(frames, file));
            AtomicFiles.writeInto(dir.resolve(SUMMARY_JSON), outDir.resolve(SUMMARY_JSON),
                    file -> SummaryJson.write(summary, file));
            AtomicFiles.writeInto(dir.resolve(FRAMETIME_PNG), outDir.resolve(FRAMETIME_PNG),
                    file -> FrameTimeChart.write(run, frames, file));
        });
        return summary;
    }
}

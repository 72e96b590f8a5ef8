package org.openworld.engine.bench;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import com.google.gson.JsonParseException;

import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

/**
 * Reads and writes {@code summary.json}: a {@link Summary} as pretty-printed JSON, one field per record component, so
 * the file is readable by people and by scripts, and {@link #read} gives back an equal record.
 */
public final class SummaryJson {

    /**
     * Pretty for people; special floating-point values allowed so that a degenerate run (e.g. every frame 0 ms, mean
     * fps infinite) still leaves a file to look at instead of failing the whole report.
     */
    private static final Gson GSON = new GsonBuilder().setPrettyPrinting().serializeSpecialFloatingPointValues()
            .create();

    private SummaryJson() {
    }

    /** Writes {@code summary} to {@code file}, replacing it. */
    public static void write(Summary summary, Path file) throws IOException {
        try (Writer out = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
            GSON.toJson(summary, out);
            out.write('\n');
        }
    }

    /**
     * Reads a summary written by {@link #write}.
     *
     * @throws SummaryFileException naming {@code file} if it is missing, unreadable, not JSON, or lacks the frame
     *                              time statistics every summary has
     */
    public static Summary read(Path file) {
        Summary summary;
        try (Reader in = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            summary = GSON.fromJson(in, Summary.class);
        } catch (NoSuchFileException e) {
            throw new SummaryFileException(file, "no such file; run 'openworld bench' first to write it", e);
        } catch (IOException e) {
            throw new SummaryFileException(file, "cannot read: " + e.getMessage(), e);
        } catch (JsonParseException e) {
            throw new SummaryFileException(file, "not valid summary JSON: " + e.getMessage(), e);
        }
        if (summary == null) {
            throw new SummaryFileException(file, "empty file, not a benchmark summary", null);
        }
        if (summary.frameMs() == null || summary.cpuMs() == null) {
            throw new SummaryFileException(file, "not a benchmark summary: no \"frameMs\" or \"cpuMs\" object", null);
        }
        return summary;
    }
}

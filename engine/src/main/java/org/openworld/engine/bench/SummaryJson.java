package org.openworld.engine.bench;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import com.google.gson.JsonParseException;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import org.openworld.engine.settings.TextFile;

/**
 * Reads and writes {@code summary.json}: a {@link Summary} as pretty-printed JSON, one field per record component, so
 * the file is readable by people and by scripts, and {@link #read} gives back an equal record.
 */
public final class SummaryJson {

    /**
     * Pretty for people; special floating-point values allowed so that a degenerate run (e.g. every frame 0 ms, mean
     * fps infinite) still leaves a file to look at instead of failing the whole report; nulls written, so that a
     * value the machine does not report (GPU memory on llvmpipe) reads as {@code null} rather than as a missing field.
     */
    private static final Gson GSON = new GsonBuilder().setPrettyPrinting().serializeSpecialFloatingPointValues()
            .serializeNulls().create();

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
     * Gson's words for what is wrong, without the Java: its message names the exception class it wraps
     * ({@code java.lang.IllegalStateException: Expected BEGIN_OBJECT but was STRING at line 3 column 1 path $}), its
     * own tokens and API, and ends with a link to its troubleshooting page. What is left is what was expected, what
     * was found and where, e.g. {@code expected an object '{' but found a string at line 3 column 1}.
     */
    static String jsonProblem(JsonParseException e) {
        String message = e.getCause() != null && e.getCause().getMessage() != null
                ? e.getCause().getMessage() : String.valueOf(e.getMessage());
        String problem = message.lines().findFirst().orElse("")
                .replaceFirst("^([\\w$]+\\.)+[\\w$]+: ", "")
                .replaceFirst("Use JsonReader\\.set\\w+\\([^)]*\\) to accept malformed JSON", "malformed JSON")
                .replaceFirst(" path \\$\\S*$", "")
                .replaceFirst("^Expected ", "expected ")
                .replace(" but was ", " but found ");
        for (String[] token : TOKENS) {
            problem = problem.replace(token[0], token[1]);
        }
        return problem;
    }

    /** Gson's token names and what a reader of the file calls them. */
    private static final String[][] TOKENS = {
        {"BEGIN_OBJECT", "an object '{'"}, {"END_OBJECT", "'}'"}, {"BEGIN_ARRAY", "a list '['"},
        {"END_ARRAY", "']'"}, {"END_DOCUMENT", "the end of the file"}, {"NAME", "a field name"},
        {"STRING", "a string"}, {"NUMBER", "a number"}, {"BOOLEAN", "true or false"}, {"NULL", "null"},
    };

    /**
     * Reads a summary written by {@link #write}.
     *
     * @throws SummaryFileException naming {@code file} if it is missing, unreadable, not JSON, or lacks the frame
     *                              time statistics every summary has
     */
    public static Summary read(Path file) {
        Summary summary;
        try {
            summary = GSON.fromJson(TextFile.read(file), Summary.class);
        } catch (NoSuchFileException e) {
            throw new SummaryFileException(file, "no such file; run 'openworld bench' first to write it", e);
        } catch (TextFile.NotTextException e) {
            throw new SummaryFileException(file, e.getMessage() + ", not a benchmark summary", e);
        } catch (IOException e) {
            throw new SummaryFileException(file, "cannot read: " + e.getMessage(), e);
        } catch (JsonParseException e) {
            throw new SummaryFileException(file, "not valid summary JSON: " + jsonProblem(e), e);
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

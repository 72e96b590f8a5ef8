package org.openworld.engine.gl;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Expands {@code #include "path"} and records where every line of the result came from, so that a driver's message
 * about a line can be put back at its file and line ({@link ShaderLog} does that).
 *
 * <p>GLSL has no includes: a stage file and everything it includes are pasted into one text. Every file pulled in
 * gets a number, its index in {@link Expanded#files()}, and {@link Expanded#origin(int)} says, for each line of the
 * text, which file and line it is. The text keeps its own line numbering, one run from 1 to the end, so a line number
 * in a driver's message finds the file by itself. It has to: the "source string" number that drivers print beside
 * the line cannot be trusted. Mesa prints 0 for most semantic errors (an undeclared name, a type mismatch) whatever
 * file the line came from, because its parser's {@code YYLLOC_DEFAULT} ({@code glsl_parser_extras.h}) sets the
 * source to 0 for every grammar rule; only syntax errors, located at a token, keep the number.
 *
 * <p>The text still carries a {@code #line LINE SOURCE} directive wherever the file changes: LINE restates the
 * text's own numbering and SOURCE is the file's number, so a raw log read by a person names the file on drivers that
 * keep the number. Since GLSL 3.30 the line after {@code #line N} is line N; before, it was N + 1, and the directive
 * is written for the stage's {@code #version}.
 *
 * <p>A program variant names {@code #define}s ({@link ShaderLibrary#program(java.util.List, String...)}): they are
 * written right after the stage's {@code #version} line, lines of ours with no origin, so one file can hold a shader's
 * variants under {@code #ifdef} and the program chosen on the CPU pays only for its own (a branch on a uniform costs
 * both sides on a software rasteriser, which runs them under masks).
 *
 * <p>Each file is included at most once per shader (like {@code #pragma once}), so headers may include each other.
 * Include paths are relative to the {@code shaders/} folder. The cost is one pass over each file's lines and one map
 * entry per line; shaders are a few hundred lines.
 */
public final class ShaderPreprocessor {

    private static final Pattern INCLUDE = Pattern.compile("^\\s*#\\s*include\\s+\"([^\"]+)\"\\s*(//.*)?$");
    private static final Pattern VERSION = Pattern.compile("^\\s*#\\s*version\\b.*");
    private static final Pattern LINE = Pattern.compile("^\\s*#\\s*line\\b.*");
    /** The number of a {@code #version} line and whether it is GLSL ES ({@code 300 es}; {@code 100} is ES 1.00). */
    private static final Pattern VERSION_NUMBER = Pattern.compile("#\\s*version\\s+(\\d+)(\\s+es\\b)?");

    /** One line of a file: its path under {@code shaders/} and its line number, from 1. */
    public record Origin(String file, int line) {
    }

    /**
     * The expanded text, the files it came from and where each of its lines came from.
     *
     * @param files   every file pulled in, the stage first; file {@code i} is source string {@code i}
     * @param origins the text's line number (from 1) to the file line it holds; the {@code #line} lines have none
     */
    public record Expanded(String source, List<String> files, Map<Integer, Origin> origins) {

        /** The file and line that line {@code line} of the expanded text holds; empty for a line of ours or none. */
        public Optional<Origin> origin(int line) {
            return Optional.ofNullable(origins.get(line));
        }
    }

    private final ShaderSources sources;

    public ShaderPreprocessor(ShaderSources sources) {
        this.sources = sources;
    }

    public Expanded expand(String path) {
        return expand(path, List.of());
    }

    /** The stage with {@code #define NAME} for each of {@code defines} after its {@code #version} line. */
    public Expanded expand(String path, List<String> defines) {
        Output out = new Output();
        out.defines = defines;
        append(path, null, 0, out, new LinkedHashSet<>());
        return new Expanded(out.text.toString(), List.copyOf(out.files), Map.copyOf(out.origins));
    }

    private void append(String path, String includer, int includerLine, Output out, Set<String> open) {
        String text = sources.read(path).orElseThrow(() -> new ShaderException(includer == null
                ? sources.displayName(path) + ": no such shader file"
                : sources.displayName(includer) + ":" + includerLine + ": cannot include \"" + path + "\": no such file"));
        int id = out.files.size();
        out.files.add(path);
        open.add(path);
        String[] lines = text.split("\r?\n", -1);
        boolean root = includer == null;
        if (root) {
            if (!VERSION.matcher(lines[0]).matches()) {
                throw new ShaderException(sources.displayName(path) + ":1: a shader stage must start with #version");
            }
            out.useLineRuleOf(lines[0]);
        }
        for (int i = 0; i < lines.length; i++) {
            int lineNo = i + 1;
            String line = lines[i];
            Matcher include = INCLUDE.matcher(line);
            if (root && i == 0) {
                out.line(line, id, lineNo);
                for (String define : out.defines) {
                    out.write("#define " + define);
                }
            } else if (VERSION.matcher(line).matches()) {
                throw new ShaderException(sources.displayName(path) + ":" + lineNo
                        + ": #version belongs only on the first line of a stage file");
            } else if (LINE.matcher(line).matches()) {
                throw new ShaderException(sources.displayName(path) + ":" + lineNo
                        + ": #line is written by the include preprocessor; remove it so errors name the right line");
            } else if (include.matches()) {
                String target = include.group(1);
                if (open.contains(target)) {
                    throw new ShaderException(sources.displayName(path) + ":" + lineNo + ": \"" + target
                            + "\" includes itself through " + String.join(" -> ", open) + " -> " + target);
                }
                if (!out.files.contains(target)) {
                    append(target, path, lineNo, out, open);
                }
            } else {
                out.line(line, id, lineNo);
            }
        }
        open.remove(path);
    }

    /** The text as it is written: its lines and their origins, the files so far, and the source string in force. */
    private static final class Output {
        final StringBuilder text = new StringBuilder();
        final List<String> files = new ArrayList<>();
        final Map<Integer, Origin> origins = new HashMap<>();
        List<String> defines = List.of();
        /** GLSL before 3.30: the line after {@code #line N} is N + 1, so N is written one less. */
        boolean lineAfterDirectiveIsOneMore;
        int lines;
        int source;

        void useLineRuleOf(String versionLine) {
            Matcher version = VERSION_NUMBER.matcher(versionLine);
            if (version.find()) {
                int number = Integer.parseInt(version.group(1));
                boolean es = version.group(2) != null || number == 100;
                lineAfterDirectiveIsOneMore = number < 330 && !es;
            }
        }

        /** Writes one line of file {@code file}, after a {@code #line} directive if the file changes. */
        void line(String line, int file, int fileLine) {
            if (file != source) {
                int next = lines + 2;
                write("#line " + (lineAfterDirectiveIsOneMore ? next - 1 : next) + " " + file);
                source = file;
            }
            write(line);
            origins.put(lines, new Origin(files.get(file), fileLine));
        }

        void write(String line) {
            text.append(line).append('\n');
            lines++;
        }
    }
}

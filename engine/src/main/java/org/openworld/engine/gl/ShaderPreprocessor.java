package org.openworld.engine.gl;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Expands {@code #include "path"} and keeps the driver's error lines traceable.
 *
 * <p>GLSL has no includes, but it has {@code #line LINE SOURCE}: it sets the line and the integer "source string"
 * number that compilers print in their messages. Each file gets a number (its index in {@link Expanded#files()}),
 * and a {@code #line} directive is written after {@code #version} and around every include, so a driver message
 * like {@code 2:14(7): error ...} reads back as {@code shaders/common/fog.glsl:14}.
 *
 * <p>Each file is included at most once per shader (like {@code #pragma once}), so headers may include each other.
 * Include paths are relative to the {@code shaders/} folder.
 */
public final class ShaderPreprocessor {

    private static final Pattern INCLUDE = Pattern.compile("^\\s*#\\s*include\\s+\"([^\"]+)\"\\s*(//.*)?$");
    private static final Pattern VERSION = Pattern.compile("^\\s*#\\s*version\\b.*");

    /** Driver log formats: Mesa {@code 0:12(5):}, NVIDIA {@code 0(12) :}, AMD/Intel {@code ERROR: 0:12:}. */
    private static final Pattern[] LOG_LOCATIONS = {
        Pattern.compile("(?m)^(\\d+):(\\d+)\\(\\d+\\)"),
        Pattern.compile("(?m)^(\\d+)\\((\\d+)\\)"),
        Pattern.compile("(?m)(?<=^(?:ERROR|WARNING): )(\\d+):(\\d+)"),
    };

    /** The expanded text and the files it came from; file {@code i} is source string {@code i}. */
    public record Expanded(String source, List<String> files) {

        /** Rewrites every "source:line" location in a driver log as "file:line". */
        public String mapLog(ShaderSources sources, String log) {
            String mapped = log;
            for (Pattern pattern : LOG_LOCATIONS) {
                Matcher m = pattern.matcher(mapped);
                StringBuilder out = new StringBuilder();
                while (m.find()) {
                    int file = Integer.parseInt(m.group(1));
                    String name = file < files.size() ? sources.displayName(files.get(file)) : "source " + file;
                    m.appendReplacement(out, Matcher.quoteReplacement(name + ":" + m.group(2)));
                }
                m.appendTail(out);
                mapped = out.toString();
            }
            return mapped.strip();
        }
    }

    private final ShaderSources sources;

    public ShaderPreprocessor(ShaderSources sources) {
        this.sources = sources;
    }

    public Expanded expand(String path) {
        List<String> files = new ArrayList<>();
        StringBuilder out = new StringBuilder();
        append(path, null, 0, files, new LinkedHashSet<>(), out);
        return new Expanded(out.toString(), List.copyOf(files));
    }

    private void append(String path, String includer, int includerLine, List<String> files, Set<String> open,
                        StringBuilder out) {
        String text = sources.read(path).orElseThrow(() -> new ShaderException(includer == null
                ? sources.displayName(path) + ": no such shader file"
                : sources.displayName(includer) + ":" + includerLine + ": cannot include \"" + path + "\": no such file"));
        int id = files.size();
        files.add(path);
        open.add(path);
        String[] lines = text.split("\r?\n", -1);
        boolean root = includer == null;
        if (root && !(lines.length > 0 && VERSION.matcher(lines[0]).matches())) {
            throw new ShaderException(sources.displayName(path) + ":1: a shader stage must start with #version");
        }
        if (!root) {
            out.append("#line 1 ").append(id).append('\n');
        }
        for (int i = 0; i < lines.length; i++) {
            int lineNo = i + 1;
            String line = lines[i];
            Matcher include = INCLUDE.matcher(line);
            if (root && i == 0) {
                out.append(line).append('\n').append("#line 2 ").append(id).append('\n');
            } else if (VERSION.matcher(line).matches()) {
                throw new ShaderException(sources.displayName(path) + ":" + lineNo
                        + ": #version belongs only on the first line of a stage file");
            } else if (include.matches()) {
                String target = include.group(1);
                if (open.contains(target)) {
                    throw new ShaderException(sources.displayName(path) + ":" + lineNo + ": \"" + target
                            + "\" includes itself through " + String.join(" -> ", open) + " -> " + target);
                }
                if (!files.contains(target)) {
                    append(target, path, lineNo, files, open, out);
                }
                out.append("#line ").append(lineNo + 1).append(' ').append(id).append('\n');
            } else {
                out.append(line).append('\n');
            }
        }
        open.remove(path);
    }
}

package org.openworld.engine.gl;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.function.Function;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Rewrites a driver's info log so that each message names the file and line it is about, in the
 * {@code file:line:column: error: ...} form that compilers use and editors jump to.
 *
 * <p>Drivers print one message a line, located by a source-string number and a line of the text they compiled. The
 * formats read here:
 * <ul>
 *   <li>Mesa (observed on Mesa 22.3, llvmpipe): {@code 0:16(20): error: `fogg' undeclared}, that is
 *       {@code SOURCE:LINE(COLUMN): error|warning|preprocessor error: ...}.</li>
 *   <li>NVIDIA: {@code 0(99) : error C1008: undefined variable "iTime"}, that is {@code SOURCE(LINE) : ...}, as its
 *       driver 375.66 printed it in github.com/simon-budig/shadertoy/issues/9.</li>
 *   <li>AMD, Intel, Apple and glslang: {@code ERROR: 0:52: 'ShadowViewProjMatrixes' : undeclared identifier}, that is
 *       {@code ERROR|WARNING: SOURCE:LINE: ...}, as quoted in github.com/supertuxkart/stk-code/issues/1308
 *       (and AMD's {@code ERROR: 0:89: error(#143) Undeclared identifier: viewPos} in
 *       github.com/yvt/openspades/issues/144).</li>
 * </ul>
 * The source number is read past: {@link ShaderPreprocessor} numbers the expanded text's lines uniquely, so the line
 * alone finds the file (Mesa prints source 0 for most semantic errors). A line in any other form, or whose line
 * number holds no file line, is kept as it is behind the stage file's name, never guessed at: a summary like
 * {@code ERROR: 1 compilation errors.  No code generated.} reads {@code shaders/sky/sky.frag: ERROR: 1 compilation
 * errors.  No code generated.}
 *
 * <p>Link logs carry no location (the linker sees whole stages); their lines are kept as they are, and
 * {@link ShaderProgram} names the stages being linked.
 */
final class ShaderLog {

    /** One message in a known format: the expanded text's line, its column (0: not given) and what it says. */
    private record Located(int line, int column, String text) {
    }

    /** The located formats: a whole-line pattern (numbers of up to 9 digits fit an int) and how it makes a Located. */
    private enum Format {
        MESA("(\\d{1,9}):(\\d{1,9})\\((\\d{1,9})\\): (.*)", m -> new Located(number(m, 2), number(m, 3), m.group(4))),
        NVIDIA("(\\d{1,9})\\((\\d{1,9})\\) ?: (.*)", m -> new Located(number(m, 2), 0, m.group(3))),
        GLSLANG("(ERROR|WARNING): (\\d{1,9}):(\\d{1,9}): (.*)",
                m -> new Located(number(m, 3), 0, severity(m.group(1), m.group(4))));

        private final Pattern pattern;
        private final Function<Matcher, Located> read;

        Format(String pattern, Function<Matcher, Located> read) {
            this.pattern = Pattern.compile(pattern);
            this.read = read;
        }
    }

    private ShaderLog() {
    }

    /**
     * A compile log, one rewritten line per message; blank lines dropped.
     *
     * @param expanded the text the driver compiled, with its lines' origins
     */
    static List<String> compile(String log, ShaderPreprocessor.Expanded expanded, ShaderSources sources) {
        String stage = sources.displayName(expanded.files().get(0));
        List<String> out = new ArrayList<>();
        for (String line : lines(log)) {
            Optional<Located> located = locate(line);
            Optional<ShaderPreprocessor.Origin> origin = located.flatMap(l -> expanded.origin(l.line()));
            if (origin.isPresent()) {
                Located at = located.get();
                out.add(sources.displayName(origin.get().file()) + ":" + origin.get().line()
                        + (at.column() > 0 ? ":" + at.column() : "") + ": " + at.text());
            } else {
                out.add(stage + ": " + line);
            }
        }
        return out;
    }

    /** A link log's lines as the driver wrote them; blank lines dropped. */
    static List<String> link(String log) {
        return lines(log);
    }

    private static List<String> lines(String log) {
        return log.lines().map(String::strip).filter(line -> !line.isEmpty()).toList();
    }

    private static Optional<Located> locate(String line) {
        for (Format format : Format.values()) {
            Matcher m = format.pattern.matcher(line);
            if (m.matches()) {
                return Optional.of(format.read.apply(m));
            }
        }
        return Optional.empty();
    }

    private static int number(Matcher m, int group) {
        return Integer.parseInt(m.group(group));
    }

    /** {@code ERROR} and the text as {@code error: text}, unless the text already starts with it (AMD's). */
    private static String severity(String word, String text) {
        String lower = word.toLowerCase(Locale.ROOT);
        return text.toLowerCase(Locale.ROOT).startsWith(lower) ? text : lower + ": " + text;
    }
}

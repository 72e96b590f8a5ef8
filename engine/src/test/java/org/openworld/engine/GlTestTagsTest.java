package org.openworld.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * No test that makes an OpenGL context is left without the {@code gl} tag ({@link GlTest}, or {@code @Tag("gl")} in
 * the demo), or {@code -Dgroups='!gl'} would run it: slowly, and on a machine without OpenGL, into a failure. The
 * test sources of both modules are read as text.
 *
 * <p>A test makes a context when its code names {@code HeadlessGl}, {@code GlContext}, {@code GlTestSupport} or
 * {@code Launch.start}, or calls {@code Main.execute} with a rendering command ({@code shot}, {@code bench},
 * {@code figures}, {@code run}, or {@code info} without {@code --frame}). The rule is conservative: a test that runs
 * a rendering command with a mistake in its arguments counts too, though it stops before the context, because a
 * scan cannot tell and the command may one day make the context first. Where the code stands decides where the tag
 * goes: in a test method's body, on that method or on its class; anywhere else (a field, a set-up method, a helper),
 * on the class. A file without tests (a helper such as {@code HeadlessGl}) is not checked itself: the tests that
 * use it name it.
 */
class GlTestTagsTest {

    /** The repository root, seen from the engine module's folder, where the tests run. */
    private static final Path ROOT = Path.of("..");

    private static final Pattern CONTEXT = Pattern.compile("\\b(HeadlessGl|GlContext|GlTestSupport|Launch\\.start)\\b");
    private static final Pattern RENDERING_COMMAND =
            Pattern.compile("\"(shot|bench|figures|run)\"|\"info\"(?!\\s*,\\s*\"--frame\")");
    private static final Pattern TAG = Pattern.compile("@GlTest\\b|@Tag\\(\\s*(GlTest\\.TAG|\"gl\")\\s*\\)");
    private static final Pattern TEST = Pattern.compile("@(Test|ParameterizedTest|RepeatedTest|TestFactory)\\b");
    private static final Pattern CLASS = Pattern.compile("(?m)^(?:public |final |abstract )*class \\w+");
    private static final Pattern METHOD_NAME = Pattern.compile("(\\w+)\\s*\\(");
    /** An annotation with its arguments, one level of parentheses inside them. */
    private static final String ANNOTATION = "@[\\w.]+(\\s*\\((?:[^()]|\\([^()]*\\))*\\))?";

    @Test
    void everyTestThatMakesAContextIsTagged() throws IOException {
        List<String> untagged = new ArrayList<>();
        for (String module : List.of("engine", "demo")) {
            try (Stream<Path> files = Files.walk(ROOT.resolve(module).resolve("src/test/java"))) {
                for (Path file : files.filter(f -> f.toString().endsWith(".java")).sorted().toList()) {
                    untagged.addAll(untagged(file.getFileName().toString(), Files.readString(file)));
                }
            }
        }
        assertEquals(List.of(), untagged, "tests that make an OpenGL context without the gl tag (@GlTest, or "
                + "@Tag(\"gl\") in the demo)");
    }

    @Test
    void theScanFindsTheRealGlTestsWithoutTheirTags() throws IOException {
        String engineTest = Files.readString(ROOT.resolve("engine/src/test/java/org/openworld/engine/EngineTest.java"));
        assertEquals("EngineTest.java: the class (HeadlessGl outside a test method)",
                untagged("EngineTest.java", engineTest.replace("@GlTest\n", "")).get(0));
        String commandLineTest = Files.readString(ROOT.resolve("demo/src/test/java/org/openworld/demo/CommandLineTest.java"));
        List<String> found = untagged("CommandLineTest.java", commandLineTest.replace("@Tag(\"gl\")", ""));
        assertTrue(found.contains("CommandLineTest.java: shotWritesAnImageOfTheAskedSize"), found.toString());
        assertTrue(found.stream().noneMatch(f -> f.contains("settingsListsEveryKeyWithItsDefault")), found.toString());
    }

    @Test
    void theScanFindsAnUntaggedContextInAFieldAndInATest() {
        String inField = "class A {\n static final HeadlessGl GL = new HeadlessGl();\n @Test void a() { }\n}\n";
        assertEquals(List.of("A.java: the class (HeadlessGl outside a test method)"), untagged("A.java", inField));
        assertEquals(List.of(), untagged("A.java", "@GlTest\n" + inField));

        String inTest = "class B {\n @Test void fast() { Main.execute(\"info\", \"--frame\"); }\n"
                + " @ParameterizedTest @EnumSource(names = {\"X\"}) void slow(M m) { if (x) { Main.execute(\"shot\", \"}\"); } }"
                + "\n}\n";
        assertEquals(List.of("B.java: slow"), untagged("B.java", inTest));
        assertEquals(List.of(), untagged("B.java", inTest.replace(" @ParameterizedTest", " @Tag(\"gl\") @ParameterizedTest")));
        assertEquals(List.of(), untagged("C.java", "class C {\n // a HeadlessGl in a comment\n @Test void c() { }\n}\n"));
    }

    /** What in one source file makes a context without the tag: "File.java: method", or "File.java: the class". */
    static List<String> untagged(String name, String source) {
        String code = withoutComments(source).replaceAll("(?m)^import .*$", "");
        String bare = withoutLiterals(code); // the same offsets, string contents blanked too
        Matcher declaration = CLASS.matcher(bare);
        if (!declaration.find() || !TEST.matcher(bare).find()
                || TAG.matcher(code.substring(0, declaration.start())).find()) {
            return List.of();
        }
        List<String> found = new ArrayList<>();
        StringBuilder outside = new StringBuilder();
        int from = 0;
        Matcher test = TEST.matcher(bare);
        while (test.find(from)) {
            int open = bodyStart(bare, test.end());
            int close = matchingBrace(bare, open);
            int head = 1 + Math.max(Math.max(bare.lastIndexOf('}', test.start()), bare.lastIndexOf(';', test.start())),
                    bare.lastIndexOf('{', test.start()));
            if (makesContext(code.substring(open, close + 1), bare.substring(open, close + 1))
                    && !TAG.matcher(code.substring(head, open)).find()) {
                Matcher method = METHOD_NAME.matcher(bare.substring(test.end(), open).replaceAll(ANNOTATION, ""));
                found.add(name + ": " + (method.find() ? method.group(1) : "a test"));
            }
            outside.append(bare, from, open);
            from = close + 1;
        }
        outside.append(bare.substring(from));
        Matcher elsewhere = CONTEXT.matcher(outside);
        if (elsewhere.find()) {
            found.add(0, name + ": the class (" + elsewhere.group(1) + " outside a test method)");
        }
        return found;
    }

    private static boolean makesContext(String code, String bare) {
        return CONTEXT.matcher(bare).find() || (bare.contains("Main.execute(") && RENDERING_COMMAND.matcher(code).find());
    }

    /** The '{' that opens the method body after {@code from}: the first outside parentheses (annotation arguments). */
    private static int bodyStart(String bare, int from) {
        int depth = 0;
        for (int i = from; i < bare.length(); i++) {
            char c = bare.charAt(i);
            depth += c == '(' ? 1 : c == ')' ? -1 : 0;
            if (c == '{' && depth == 0) {
                return i;
            }
        }
        throw new IllegalArgumentException("no method body after offset " + from);
    }

    /** The '}' that closes the '{' at {@code open}. */
    private static int matchingBrace(String bare, int open) {
        int depth = 0;
        for (int i = open; i < bare.length(); i++) {
            char c = bare.charAt(i);
            depth += c == '{' ? 1 : c == '}' ? -1 : 0;
            if (depth == 0) {
                return i;
            }
        }
        throw new IllegalArgumentException("unbalanced braces from offset " + open);
    }

    /** The last index of the string, text block or character literal starting at i, or i itself when none does. */
    private static int literalEnd(String code, int i) {
        char c = code.charAt(i);
        if (c != '"' && c != '\'') {
            return i;
        }
        if (code.startsWith("\"\"\"", i)) {
            return code.indexOf("\"\"\"", i + 3) + 2;
        }
        int j = i + 1;
        while (code.charAt(j) != c) {
            j += code.charAt(j) == '\\' ? 2 : 1;
        }
        return j;
    }

    /** The source with its comments blanked out (line breaks kept), so a name in prose does not count. */
    static String withoutComments(String source) {
        StringBuilder code = new StringBuilder(source);
        int i = 0;
        while (i < source.length()) {
            int end = literalEnd(source, i);
            if (end != i) {
                i = end + 1;
            } else if (source.startsWith("//", i) || source.startsWith("/*", i)) {
                int close = source.startsWith("//", i) ? source.indexOf('\n', i) : source.indexOf("*/", i) + 2;
                close = close < i ? source.length() : close;
                blank(code, i, close);
                i = close;
            } else {
                i++;
            }
        }
        return code.toString();
    }

    /** The code with the contents of its string and character literals blanked out, quotes kept. */
    static String withoutLiterals(String code) {
        StringBuilder bare = new StringBuilder(code);
        for (int i = 0; i < code.length(); i++) {
            int end = literalEnd(code, i);
            blank(bare, i + 1, end);
            i = end;
        }
        return bare.toString();
    }

    private static void blank(StringBuilder text, int from, int to) {
        for (int k = from; k < to; k++) {
            if (text.charAt(k) != '\n') {
                text.setCharAt(k, ' ');
            }
        }
    }
}

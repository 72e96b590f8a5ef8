package org.openworld.engine.gl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/** Include expansion and driver-log mapping, over in-memory files (no GL). */
class ShaderPreprocessorTest {

    static ShaderSources files(Map<String, String> files) {
        return path -> Optional.ofNullable(files.get(path));
    }

    /** main.frag includes b and c; both include d (a diamond). */
    static final ShaderSources DIAMOND = files(Map.of(
            "main.frag", """
                    #version 330 core
                    #include "b.glsl"
                    #include "c.glsl"
                    void main() {}""",
            "b.glsl", """
                    #include "d.glsl"
                    float b() { return d(); }""",
            "c.glsl", """
                    #include "d.glsl" // c needs d as well
                    float c() { return d(); }""",
            "d.glsl", """
                    float d() { return 1.0; }"""));

    static int count(String text, String part) {
        int n = 0;
        for (int i = text.indexOf(part); i >= 0; i = text.indexOf(part, i + 1)) {
            n++;
        }
        return n;
    }

    @Test
    void diamondIncludeIsExpandedOnce() {
        ShaderPreprocessor.Expanded expanded = new ShaderPreprocessor(DIAMOND).expand("main.frag");

        assertEquals(1, count(expanded.source(), "float d()"), expanded.source());
        assertEquals(1, count(expanded.source(), "float b()"), expanded.source());
        assertEquals(1, count(expanded.source(), "float c()"), expanded.source());
        assertEquals(0, count(expanded.source(), "#include"), expanded.source());
        assertTrue(expanded.source().startsWith("#version 330 core\n"), expanded.source());
        assertEquals(List.of("main.frag", "b.glsl", "d.glsl", "c.glsl"), expanded.files());
        // d is defined before b uses it
        assertTrue(expanded.source().indexOf("float d()") < expanded.source().indexOf("float b()"));
    }

    /** Where each marker of {@link #NESTED} is: its file and line. */
    static final Map<String, String> NESTED_MARKERS = Map.of(
            "marker_lit", "lit.frag:4",
            "marker_fog", "common/fog.glsl:4",
            "marker_frame", "common/frame.glsl:2",
            "marker_end", "lit.frag:6");

    /** lit.frag includes fog, which includes frame; lit goes on after its include. */
    static final ShaderSources NESTED = files(Map.of(
            "lit.frag", """
                    #version 330 core
                    #include "common/fog.glsl"
                    // a comment
                    float marker_lit;
                    #include "common/frame.glsl"
                    float marker_end;""",
            "common/fog.glsl", """
                    // fog
                    #include "common/frame.glsl"

                    float marker_fog;""",
            "common/frame.glsl", """
                    // frame
                    float marker_frame;"""));

    /** The expanded text's line number (from 1) of the line that holds {@code marker}. */
    static int lineOf(String expanded, String marker) {
        List<String> lines = expanded.lines().toList();
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).contains(marker)) {
                return i + 1;
            }
        }
        throw new AssertionError(marker + " not in " + expanded);
    }

    @Test
    void everyLineOfTheTextKnowsItsFileAndLine() {
        ShaderPreprocessor.Expanded expanded = new ShaderPreprocessor(NESTED).expand("lit.frag");

        NESTED_MARKERS.forEach((marker, place) -> {
            ShaderPreprocessor.Origin origin = expanded.origin(lineOf(expanded.source(), marker)).orElseThrow();
            assertEquals(place, origin.file() + ":" + origin.line(), marker);
        });
        assertEquals("lit.frag:1", expanded.origin(1).map(o -> o.file() + ":" + o.line()).orElseThrow());
        // The #line directives are the preprocessor's own lines: they hold no file line.
        List<String> lines = expanded.source().lines().toList();
        for (int i = 0; i < lines.size(); i++) {
            assertEquals(!lines.get(i).startsWith("#line"), expanded.origin(i + 1).isPresent(), lines.get(i));
        }
    }

    @Test
    void definesFollowTheVersionLineAndLeaveEveryFileLineItsOrigin() {
        ShaderPreprocessor.Expanded expanded =
                new ShaderPreprocessor(NESTED).expand("lit.frag", List.of("VARIANT_A", "VARIANT_B"));

        List<String> lines = expanded.source().lines().toList();
        assertEquals(List.of("#define VARIANT_A", "#define VARIANT_B"), lines.subList(1, 3));
        assertTrue(expanded.origin(2).isEmpty() && expanded.origin(3).isEmpty(), "the defines are lines of ours");
        NESTED_MARKERS.forEach((marker, place) -> {
            ShaderPreprocessor.Origin origin = expanded.origin(lineOf(expanded.source(), marker)).orElseThrow();
            assertEquals(place, origin.file() + ":" + origin.line(), marker);
            assertEquals(lineOf(expanded.source(), marker), driverLocation(expanded.source(), marker, false)[1], marker);
        });
    }

    /**
     * Simulates a driver reading the text: the file number and line it gives a marker, following the #line directives
     * (since GLSL 3.30 the line after {@code #line N} is N; before, N + 1).
     */
    static int[] driverLocation(String expanded, String marker, boolean before330) {
        int file = 0;
        int line = 1;
        for (String l : expanded.lines().toList()) {
            if (l.startsWith("#line ")) {
                String[] parts = l.split(" ");
                line = Integer.parseInt(parts[1]) + (before330 ? 1 : 0);
                file = Integer.parseInt(parts[2]);
                continue;
            }
            if (l.contains(marker)) {
                return new int[] {file, line};
            }
            line++;
        }
        throw new AssertionError(marker + " not in " + expanded);
    }

    @Test
    void aDriverSeesTheTextsOwnLineNumbersAndEachFilesNumber() {
        ShaderPreprocessor.Expanded expanded = new ShaderPreprocessor(NESTED).expand("lit.frag");

        for (String marker : NESTED_MARKERS.keySet()) {
            int[] seen = driverLocation(expanded.source(), marker, false);
            int line = lineOf(expanded.source(), marker);
            assertEquals(line, seen[1], marker);
            assertEquals(expanded.origin(line).orElseThrow().file(), expanded.files().get(seen[0]), marker);
        }
        assertEquals(List.of("lit.frag", "common/fog.glsl", "common/frame.glsl"), expanded.files());
    }

    @Test
    void beforeGlsl330TheDirectivesAreWrittenOneLess() {
        ShaderSources old = files(Map.of(
                "old.frag", "#version 150\n#include \"b.glsl\"\nfloat marker_old;",
                "b.glsl", "// b\nfloat marker_b;"));
        ShaderPreprocessor.Expanded expanded = new ShaderPreprocessor(old).expand("old.frag");

        for (String marker : List.of("marker_old", "marker_b")) {
            assertEquals(lineOf(expanded.source(), marker), driverLocation(expanded.source(), marker, true)[1], marker);
        }
    }

    @Test
    void glslEsVersionsUseTheNewRule() {
        for (String version : List.of("#version 300 es", "#version 100")) {
            ShaderSources es = files(Map.of(
                    "es.frag", version + "\n#include \"b.glsl\"\nfloat marker_es;",
                    "b.glsl", "float marker_b;"));
            String source = new ShaderPreprocessor(es).expand("es.frag").source();

            assertEquals(lineOf(source, "marker_es"), driverLocation(source, "marker_es", false)[1], version);
        }
    }

    @Test
    void aLineDirectiveInAShaderFileIsRefused() {
        ShaderSources sources = files(Map.of(
                "a.frag", "#version 330 core\n#include \"b.glsl\"\n",
                "b.glsl", "// b\n#line 40 0\n"));

        ShaderException e = assertThrows(ShaderException.class, () -> new ShaderPreprocessor(sources).expand("a.frag"));

        assertTrue(e.getMessage().startsWith("shaders/b.glsl:2: #line"), e.getMessage());
    }

    @Test
    void missingIncludeNamesTheIncludingFileAndLine() {
        ShaderSources sources = files(Map.of("a.frag", "#version 330 core\n#include \"x.glsl\"\nvoid main() {}"));

        ShaderException e = assertThrows(ShaderException.class, () -> new ShaderPreprocessor(sources).expand("a.frag"));

        assertEquals("shaders/a.frag:2: cannot include \"x.glsl\": no such file", e.getMessage());
    }

    @Test
    void missingStageFileIsNamed() {
        ShaderException e = assertThrows(ShaderException.class,
                () -> new ShaderPreprocessor(files(Map.of())).expand("sky/sky.frag"));

        assertTrue(e.getMessage().contains("shaders/sky/sky.frag"), e.getMessage());
    }

    @Test
    void includeCycleIsAnError() {
        ShaderSources sources = files(Map.of(
                "a.frag", "#version 330 core\n#include \"p.glsl\"\n",
                "p.glsl", "#include \"q.glsl\"\n",
                "q.glsl", "// q\n#include \"p.glsl\"\n"));

        ShaderException e = assertThrows(ShaderException.class, () -> new ShaderPreprocessor(sources).expand("a.frag"));

        assertTrue(e.getMessage().startsWith("shaders/q.glsl:2:"), e.getMessage());
        assertTrue(e.getMessage().contains("p.glsl -> q.glsl -> p.glsl"), e.getMessage());
    }

    @Test
    void stageWithoutVersionIsAnErrorOnLine1() {
        ShaderSources sources = files(Map.of("a.frag", "#include \"b.glsl\"\nvoid main() {}"));

        ShaderException e = assertThrows(ShaderException.class, () -> new ShaderPreprocessor(sources).expand("a.frag"));

        assertTrue(e.getMessage().startsWith("shaders/a.frag:1:"), e.getMessage());
        assertTrue(e.getMessage().contains("#version"), e.getMessage());
    }

    @Test
    void versionInsideAnIncludeIsAnError() {
        ShaderSources sources = files(Map.of(
                "a.frag", "#version 330 core\n#include \"b.glsl\"\n",
                "b.glsl", "// b\n#version 330 core\n"));

        ShaderException e = assertThrows(ShaderException.class, () -> new ShaderPreprocessor(sources).expand("a.frag"));

        assertTrue(e.getMessage().startsWith("shaders/b.glsl:2:"), e.getMessage());
    }
}

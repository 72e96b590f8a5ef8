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

    @Test
    void lineDirectivesNameEachFileAndTheLineAfterAnInclude() {
        String source = new ShaderPreprocessor(DIAMOND).expand("main.frag").source();
        List<String> lines = source.lines().toList();

        // After #version the root continues at its line 2 as source string 0.
        assertEquals("#line 2 0", lines.get(1));
        // Each included file starts at its line 1 under its own number (b = 1, d = 2, c = 3).
        assertTrue(lines.contains("#line 1 1"), source);
        assertTrue(lines.contains("#line 1 2"), source);
        assertTrue(lines.contains("#line 1 3"), source);
        // Back in main.frag after the include on line 3, the next line is line 4.
        int mainBody = lines.indexOf("void main() {}");
        assertEquals("#line 4 0", lines.get(mainBody - 1), source);
        // Back in c.glsl after its include on line 1, the next line is line 2.
        int cBody = lines.indexOf("float c() { return d(); }");
        assertEquals("#line 2 3", lines.get(cBody - 1), source);
    }

    /** Simulates a driver: finds which file and line the expanded text's #line directives give a marker. */
    static int[] locate(String expanded, String marker) {
        int file = 0;
        int line = 1;
        for (String l : expanded.lines().toList()) {
            if (l.startsWith("#line ")) {
                String[] parts = l.split(" ");
                line = Integer.parseInt(parts[1]);
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
    void lineDirectivesPutEveryLineBackAtItsFileAndLine() {
        ShaderSources sources = files(Map.of(
                "lit.frag", """
                        #version 330 core
                        #include "common/fog.glsl"
                        // a comment
                        float marker_lit;""",
                "common/fog.glsl", """
                        // fog
                        #include "common/frame.glsl"

                        float marker_fog;""",
                "common/frame.glsl", """
                        // frame
                        float marker_frame;"""));
        ShaderPreprocessor.Expanded expanded = new ShaderPreprocessor(sources).expand("lit.frag");

        int[] lit = locate(expanded.source(), "marker_lit");
        int[] fog = locate(expanded.source(), "marker_fog");
        int[] frame = locate(expanded.source(), "marker_frame");
        assertEquals("lit.frag:4", expanded.files().get(lit[0]) + ":" + lit[1]);
        assertEquals("common/fog.glsl:4", expanded.files().get(fog[0]) + ":" + fog[1]);
        assertEquals("common/frame.glsl:2", expanded.files().get(frame[0]) + ":" + frame[1]);
    }

    @Test
    void mapLogRewritesMesaAndNvidiaLocations() {
        ShaderPreprocessor.Expanded expanded = new ShaderPreprocessor(DIAMOND).expand("main.frag");

        String mesa = expanded.mapLog(DIAMOND, "1:3(5): error: syntax error, unexpected IDENTIFIER\n");
        String nvidia = expanded.mapLog(DIAMOND, "1(3) : error C0000: syntax error, unexpected identifier\n");
        String intel = expanded.mapLog(DIAMOND, "ERROR: 2:7: 'x' : undeclared identifier\n");

        assertEquals("shaders/b.glsl:3: error: syntax error, unexpected IDENTIFIER", mesa);
        assertEquals("shaders/b.glsl:3 : error C0000: syntax error, unexpected identifier", nvidia);
        assertEquals("ERROR: shaders/d.glsl:7: 'x' : undeclared identifier", intel);
    }

    @Test
    void mapLogRewritesEveryLineOfAMultiLineLog() {
        ShaderPreprocessor.Expanded expanded = new ShaderPreprocessor(DIAMOND).expand("main.frag");

        String mapped = expanded.mapLog(DIAMOND, "0:4(1): error: first\n3:2(9): warning: second\n");

        assertEquals("shaders/main.frag:4: error: first\nshaders/c.glsl:2: warning: second", mapped);
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

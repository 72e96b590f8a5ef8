package org.openworld.engine.gl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.openworld.engine.gl.ShaderPreprocessorTest.files;
import static org.openworld.engine.gl.ShaderPreprocessorTest.lineOf;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * Driver logs rewritten to file and line, without GL: the logs are written by hand in each driver's format, at the
 * line numbers of the expanded text that driver would have compiled. Mesa's format is the one llvmpipe prints here
 * ({@code ShaderProgramTest} checks it on the real driver); NVIDIA's and the AMD/Intel one are the observed formats
 * cited in {@link ShaderLog}.
 */
class ShaderLogTest {

    /** terrain.frag includes fog.glsl, whose line 15 uses an undeclared name; terrain.frag goes on after it. */
    static final ShaderSources SOURCES = files(Map.of(
            "terrain/terrain.frag", """
                    #version 330 core
                    #include "common/fog.glsl"
                    out vec4 fragColor;
                    void main() { fragColor = vec4(fog(1.0) * undeclaredGain); }""",
            "common/fog.glsl", "// fog\n".repeat(14) + "float fog(float d) { return d * fogg; }\n"));

    static final ShaderPreprocessor.Expanded EXPANDED = new ShaderPreprocessor(SOURCES).expand("terrain/terrain.frag");

    /** The expanded line of fog.glsl's line 15 and of terrain.frag's line 4. */
    static final int FOG_15 = lineOf(EXPANDED.source(), "fogg");
    static final int TERRAIN_4 = lineOf(EXPANDED.source(), "undeclaredGain");

    static List<String> map(String log) {
        return ShaderLog.compile(log, EXPANDED, SOURCES);
    }

    @Test
    void mesaSemanticErrorWithSourceZeroIsPutInTheIncludedFile() {
        // Mesa prints source string 0 for a semantic error whatever file it is in; the line finds the file.
        List<String> mapped = map("0:" + FOG_15 + "(29): error: `fogg' undeclared\n"
                + "1:" + FOG_15 + "(22): error: `return' with wrong type error, in function `fog' returning float\n");

        assertEquals(List.of("shaders/common/fog.glsl:15:29: error: `fogg' undeclared",
                "shaders/common/fog.glsl:15:22: error: `return' with wrong type error, in function `fog' returning float"),
                mapped);
    }

    @Test
    void mesaErrorInTheStageAfterAnIncludeNamesTheStageLine() {
        List<String> mapped = map("0:" + TERRAIN_4 + "(42): error: `undeclaredGain' undeclared\n");

        assertEquals(List.of("shaders/terrain/terrain.frag:4:42: error: `undeclaredGain' undeclared"), mapped);
    }

    @Test
    void nvidiaFormat() {
        List<String> mapped = map("0(" + FOG_15 + ") : error C1008: undefined variable \"fogg\"\n"
                + "0(" + TERRAIN_4 + ") : warning C7050: \"undeclaredGain\" might be used before being initialized\n");

        assertEquals(List.of("shaders/common/fog.glsl:15: error C1008: undefined variable \"fogg\"",
                "shaders/terrain/terrain.frag:4: warning C7050: \"undeclaredGain\" might be used before being initialized"),
                mapped);
    }

    @Test
    void amdAndIntelFormat() {
        List<String> mapped = map("ERROR: 0:" + FOG_15 + ": 'fogg' : undeclared identifier \n"
                + "ERROR: 0:" + TERRAIN_4 + ": error(#143) Undeclared identifier: undeclaredGain\n"
                + "WARNING: 0:" + TERRAIN_4 + ": implicit conversion\n");

        assertEquals(List.of("shaders/common/fog.glsl:15: error: 'fogg' : undeclared identifier",
                "shaders/terrain/terrain.frag:4: error(#143) Undeclared identifier: undeclaredGain",
                "shaders/terrain/terrain.frag:4: warning: implicit conversion"), mapped);
    }

    @Test
    void unknownFormatsAndLinesOutsideAnyFileAreKeptBehindTheStageFile() {
        int directive = lineOf(EXPANDED.source(), "#line");
        List<String> mapped = map("ERROR: 2 compilation errors.  No code generated.\n\n"
                + "0:" + directive + "(1): error: on a line of the preprocessor's own\n"
                + "0:99999(1): error: past the end\n"
                + "Fragment info\n");

        assertEquals(List.of("shaders/terrain/terrain.frag: ERROR: 2 compilation errors.  No code generated.",
                "shaders/terrain/terrain.frag: 0:" + directive + "(1): error: on a line of the preprocessor's own",
                "shaders/terrain/terrain.frag: 0:99999(1): error: past the end",
                "shaders/terrain/terrain.frag: Fragment info"), mapped);
    }

    @Test
    void linkLogLinesAreKeptWithoutBlanks() {
        assertEquals(List.of("error: unresolved reference to function `g'", "second"),
                ShaderLog.link("error: unresolved reference to function `g'\n\n  second  \n"));
    }
}

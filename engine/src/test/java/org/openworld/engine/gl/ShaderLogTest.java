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

    /** Asserts that the compile log {@code log} is rewritten as the lines {@code expected}. */
    static void assertMaps(String log, String... expected) {
        assertEquals(List.of(expected), ShaderLog.compile(log, EXPANDED, SOURCES));
    }

    @Test
    void mesaSemanticErrorWithSourceZeroIsPutInTheIncludedFile() {
        // Mesa prints source string 0 for a semantic error whatever file it is in; the line finds the file.
        assertMaps("0:" + FOG_15 + "(29): error: `fogg' undeclared\n"
                + "1:" + FOG_15 + "(22): error: `return' with wrong type error, in function `fog' returning float\n",
                "shaders/common/fog.glsl:15:29: error: `fogg' undeclared",
                "shaders/common/fog.glsl:15:22: error: `return' with wrong type error, in function `fog' returning"
                        + " float");
    }

    @Test
    void mesaErrorInTheStageAfterAnIncludeNamesTheStageLine() {
        assertMaps("0:" + TERRAIN_4 + "(42): error: `undeclaredGain' undeclared\n",
                "shaders/terrain/terrain.frag:4:42: error: `undeclaredGain' undeclared");
    }

    @Test
    void nvidiaFormat() {
        assertMaps("0(" + FOG_15 + ") : error C1008: undefined variable \"fogg\"\n"
                + "0(" + TERRAIN_4 + ") : warning C7050: \"undeclaredGain\" might be used before being initialized\n",
                "shaders/common/fog.glsl:15: error C1008: undefined variable \"fogg\"",
                "shaders/terrain/terrain.frag:4: warning C7050: \"undeclaredGain\" might be used before being"
                        + " initialized");
    }

    @Test
    void amdAndIntelFormat() {
        assertMaps("ERROR: 0:" + FOG_15 + ": 'fogg' : undeclared identifier \n"
                + "ERROR: 0:" + TERRAIN_4 + ": error(#143) Undeclared identifier: undeclaredGain\n"
                + "WARNING: 0:" + TERRAIN_4 + ": implicit conversion\n",
                "shaders/common/fog.glsl:15: error: 'fogg' : undeclared identifier",
                "shaders/terrain/terrain.frag:4: error(#143) Undeclared identifier: undeclaredGain",
                "shaders/terrain/terrain.frag:4: warning: implicit conversion");
    }

    @Test
    void unknownFormatsAndLinesOutsideAnyFileAreKeptBehindTheStageFile() {
        int directive = lineOf(EXPANDED.source(), "#line");
        assertMaps("ERROR: 2 compilation errors.  No code generated.\n\n"
                + "0:" + directive + "(1): error: on a line of the preprocessor's own\n"
                + "0:99999(1): error: past the end\n"
                + "Fragment info\n",
                "shaders/terrain/terrain.frag: ERROR: 2 compilation errors.  No code generated.",
                "shaders/terrain/terrain.frag: 0:" + directive + "(1): error: on a line of the preprocessor's own",
                "shaders/terrain/terrain.frag: 0:99999(1): error: past the end",
                "shaders/terrain/terrain.frag: Fragment info");
    }

    @Test
    void linkLogLinesAreKeptWithoutBlanks() {
        assertEquals(List.of("error: unresolved reference to function `g'", "second"),
                ShaderLog.link("error: unresolved reference to function `g'\n\n  second  \n"));
    }
}

package org.openworld.engine.gl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL11C.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.openworld.engine.GlTest;
import org.openworld.engine.HeadlessGl;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.GlTestSupport;

/**
 * Programs built by the real driver (Mesa llvmpipe here) from files on disk, as in dev mode: error locations mapped
 * back through includes (syntax and semantic errors, nested includes, lines after an include, a pre-3.30 stage),
 * link errors naming their stages, missing uniforms, and reloads that fail or succeed.
 */
@GlTest
class ShaderProgramTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    @TempDir
    Path dir;

    private void write(String path, String text) throws IOException {
        Path file = dir.resolve(path);
        Files.createDirectories(file.getParent());
        Files.writeString(file, text);
    }

    private static final String VERTEX = """
            #version 330 core
            layout(location = 0) in vec2 csCorner;
            void main() { gl_Position = vec4(csCorner, 0.0, 1.0); }
            """;

    private static final String FRAGMENT = """
            #version 330 core
            #include "lib/tint.glsl"
            uniform vec4 uScale;
            out vec4 fragColor;
            void main() { fragColor = vec4(tint(), 1.0) * uScale; }
            """;

    /** The lines of a shader error's message after its heading: the driver's log, rewritten. */
    private static List<String> logLines(ShaderException e) {
        List<String> lines = e.getMessage().lines().toList();
        return lines.subList(1, lines.size());
    }

    /** Whether some line of the log starts with {@code place}, e.g. "/tmp/x/common/fog.glsl:15:". */
    private static boolean reports(ShaderException e, String place, String text) {
        return logLines(e).stream().anyMatch(line -> line.startsWith(place) && line.contains(text));
    }

    @Test
    void semanticErrorInAnIncludedFileNamesThatFileAndLine() throws IOException {
        // The case a hostile pass found: Mesa gives an undeclared name the source number 0, whatever file it is in.
        write("fill.vert", VERTEX);
        write("fill.frag", FRAGMENT.replace("lib/tint.glsl", "common/fog.glsl"));
        write("common/fog.glsl", "// fog\n".repeat(14) + """
                vec3 tint() { return vec3(fogg); }
                """);
        ShaderLibrary library = new ShaderLibrary(GL.context(), ShaderSources.directory(dir));

        ShaderException e = assertThrows(ShaderException.class, () -> library.program("fill.vert", "fill.frag"));

        String fog = dir.resolve("common/fog.glsl").toString();
        assertEquals("program fill.vert+fill.frag: " + dir.resolve("fill.frag") + " (with " + fog
                + ") did not compile:",
                e.getMessage().lines().findFirst().orElseThrow());
        assertTrue(reports(e, fog + ":15:", "fogg"), e.getMessage());
        // Every line of the driver's log is put at a file line: none is left to name the stage file alone.
        assertTrue(logLines(e).stream().allMatch(line -> line.startsWith(fog + ":15:")), e.getMessage());
    }

    @Test
    void withDebugOutputTheCompilersMessagesNameTheirFilesToo() throws IOException {
        // --dev prints the driver's messages; the compiler's would name lines of the expanded text, so the debug
        // output leaves them out and the program hands over its log, mapped: a warning as a line at its file
        write("fill.vert", VERTEX);
        write("fill.frag", FRAGMENT);
        // a source of its own: Mesa's shader cache gives a text it compiled before (another run) no log at all
        write("lib/tint.glsl", "// run " + System.nanoTime() + """

                vec3 tint() {
                    float unset;
                    return vec3(unset);
                }
                """);
        ShaderLibrary library = new ShaderLibrary(GL.context(), ShaderSources.directory(dir));
        List<String> printed = new ArrayList<>();
        GL.context().debug().printMessages(printed::add);
        try {
            library.program("fill.vert", "fill.frag").close();
            String tint = dir.resolve("lib/tint.glsl").toString();
            assertTrue(printed.stream().anyMatch(line -> line.startsWith("GL shader compiler: " + tint + ":4:")
                    && line.contains("unset")), printed.toString());

            printed.clear();
            write("lib/tint.glsl", "// run " + System.nanoTime() + "\nvec3 tint() { return vec3(fogg); }\n");
            ShaderLibrary broken = new ShaderLibrary(GL.context(), ShaderSources.directory(dir));
            assertThrows(ShaderException.class, () -> broken.program("fill.vert", "fill.frag"));
            assertTrue(printed.stream().noneMatch(line -> line.contains("fogg")),
                    "a failed compile is reported once, mapped, by its exception: " + printed);
        } finally {
            GL.context().debug().printMessages(null);
        }
    }

    @Test
    void syntaxErrorInAnIncludedFileNamesThatFileAndLine() throws IOException {
        write("fill.vert", VERTEX);
        write("fill.frag", FRAGMENT);
        write("lib/tint.glsl", """
                // The colour every pixel gets.
                vec3 tint() {
                    return vec3(1.0, 0.0, 0.0) +;
                }
                """);
        ShaderLibrary library = new ShaderLibrary(GL.context(), ShaderSources.directory(dir));

        ShaderException e = assertThrows(ShaderException.class, () -> library.program("fill.vert", "fill.frag"));

        assertTrue(reports(e, dir.resolve("lib/tint.glsl") + ":3:", "syntax error"), e.getMessage());
        assertTrue(e.getMessage().contains("did not compile"), e.getMessage());
    }

    @Test
    void errorInTheStageAfterAnIncludeNamesTheStageLine() throws IOException {
        write("fill.vert", VERTEX);
        write("fill.frag", FRAGMENT.replace("* uScale;", "* uScale * undeclaredFactor;"));
        write("lib/tint.glsl", "// tint\n".repeat(12) + "vec3 tint() { return vec3(1.0); }\n");
        ShaderLibrary library = new ShaderLibrary(GL.context(), ShaderSources.directory(dir));

        ShaderException e = assertThrows(ShaderException.class, () -> library.program("fill.vert", "fill.frag"));

        assertTrue(reports(e, dir.resolve("fill.frag") + ":5:", "undeclaredFactor"), e.getMessage());
    }

    @Test
    void nestedIncludesNameEachFileAndLine() throws IOException {
        // fill.frag -> lib/outer.glsl -> lib/inner.glsl, an undeclared name in each, after each include.
        write("fill.vert", VERTEX);
        write("fill.frag", FRAGMENT.replace("lib/tint.glsl", "lib/outer.glsl").replace("* uScale;", "* missingTop;"));
        write("lib/outer.glsl", """
                // outer
                #include "lib/inner.glsl"
                // after the nested include
                vec3 tint() { return inner() * missingOuter; }
                """);
        write("lib/inner.glsl", """
                // inner
                // ...
                vec3 inner() { return vec3(missingInner); }
                """);
        ShaderLibrary library = new ShaderLibrary(GL.context(), ShaderSources.directory(dir));

        ShaderException e = assertThrows(ShaderException.class, () -> library.program("fill.vert", "fill.frag"));

        assertTrue(reports(e, dir.resolve("lib/inner.glsl") + ":3:", "missingInner"), e.getMessage());
        assertTrue(reports(e, dir.resolve("lib/outer.glsl") + ":4:", "missingOuter"), e.getMessage());
        assertTrue(reports(e, dir.resolve("fill.frag") + ":5:", "missingTop"), e.getMessage());
    }

    @Test
    void aStageBeforeGlsl330IsMappedToo() throws IOException {
        // Before GLSL 3.30 the line after #line N is N + 1: the preprocessor writes its directives for that rule.
        write("old.vert", VERTEX.replace("330 core", "150").replace("layout(location = 0) ", ""));
        write("old.frag", """
                #version 150
                #include "lib/tint.glsl"
                out vec4 fragColor;
                void main() { fragColor = vec4(tint() * missingOld, 1.0); }
                """);
        write("lib/tint.glsl", "// tint\nvec3 tint() { return vec3(missingTint); }\n");
        ShaderLibrary library = new ShaderLibrary(GL.context(), ShaderSources.directory(dir));

        ShaderException e = assertThrows(ShaderException.class, () -> library.program("old.vert", "old.frag"));

        assertTrue(reports(e, dir.resolve("lib/tint.glsl") + ":2:", "missingTint"), e.getMessage());
        assertTrue(reports(e, dir.resolve("old.frag") + ":4:", "missingOld"), e.getMessage());
    }

    @Test
    void linkErrorNamesTheStagesBeingLinked() throws IOException {
        write("fill.vert", VERTEX.replace("void main() {", "out vec2 vTint;\nvoid main() { vTint = csCorner;"));
        write("fill.frag", """
                #version 330 core
                in vec3 vTint;
                out vec4 fragColor;
                void main() { fragColor = vec4(vTint, 1.0); }
                """);
        ShaderLibrary library = new ShaderLibrary(GL.context(), ShaderSources.directory(dir));

        ShaderException e = assertThrows(ShaderException.class, () -> library.program("fill.vert", "fill.frag"));

        assertEquals("program fill.vert+fill.frag: linking the vertex stage " + dir.resolve("fill.vert")
                + " and the fragment stage " + dir.resolve("fill.frag") + " failed:",
                e.getMessage().lines().findFirst().orElseThrow());
        assertTrue(logLines(e).stream().anyMatch(line -> line.contains("vTint")), e.getMessage());
    }

    @Test
    void missingUniformIsNamed() throws IOException {
        write("fill.vert", VERTEX);
        write("fill.frag", FRAGMENT);
        write("lib/tint.glsl", "vec3 tint() { return vec3(1.0); }\n");
        ShaderLibrary library = new ShaderLibrary(GL.context(), ShaderSources.directory(dir));

        try (ShaderProgram program = library.program("fill.vert", "fill.frag")) {
            program.vec4("uScale");
            ShaderException e = assertThrows(ShaderException.class, () -> program.vec4("uScal"));
            assertTrue(e.getMessage().contains("'uScal'"), e.getMessage());
            assertTrue(e.getMessage().contains("fill.frag"), e.getMessage());
        }
    }

    @Test
    void aProgramCompiledOnFirstUseLinksThenWithTheValuesSetBefore() throws IOException {
        write("fill.vert", VERTEX);
        write("fill.frag", FRAGMENT);
        write("lib/tint.glsl", "vec3 tint() { return vec3(1.0); }\n");
        ShaderLibrary library = new ShaderLibrary(GL.context(), ShaderSources.directory(dir), true, Map.of());
        int programs = GL.context().objects().live(GlObjects.Kind.PROGRAM);

        try (ShaderProgram program = library.program("fill.vert", "fill.frag");
             Framebuffer target = new Framebuffer(GL.context(), 8, 8, Format.RGBA8, null, Sampling.NEAREST_CLAMP);
             Mesh triangle = GlTestSupport.fullScreenTriangle(GL.context())) {
            Uniform.Vec4 scale = program.vec4("uScale");
            scale.set(0.5f, 0.5f, 0.5f, 1);
            assertEquals(programs, GL.context().objects().live(GlObjects.Kind.PROGRAM), "nothing compiled before use");
            target.bind();
            program.use();
            assertEquals(programs + 1, GL.context().objects().live(GlObjects.Kind.PROGRAM), "linked by its first use");
            triangle.draw(new DrawStats());
            // the value set before the link is the one drawn with: white tint times 0.5, in 8 bits 127 or 128
            int red = target.read().channel(4, 4, 0);
            assertTrue(Math.abs(red - 127.5) <= 0.5, "red " + red);
        }
    }

    @Test
    void aLibrarysConstantsAreDefinedInEveryProgram() throws IOException {
        write("fill.vert", VERTEX);
        write("fill.frag", FRAGMENT);
        write("lib/tint.glsl", "vec3 tint() { return vec3(SHARED_GREY); }\n");
        ShaderLibrary library = new ShaderLibrary(GL.context(), ShaderSources.directory(dir), true,
                Map.of("SHARED_GREY", 0.25));
        try (ShaderProgram program = library.program("fill.vert", "fill.frag")) {
            int[] grey = draw(program, program.vec4("uScale"), 1);
            assertEquals(64, grey[0], 1); // 0.25 · 255 = 63.75, rounded by the 8-bit target
        }
        ShaderLibrary without = new ShaderLibrary(GL.context(), ShaderSources.directory(dir));
        assertThrows(ShaderException.class, () -> without.program("fill.vert", "fill.frag"), "SHARED_GREY undefined");
    }

    @Test
    void aProgramCompiledOnFirstUseNamesItsErrorsThen() throws IOException {
        write("fill.vert", VERTEX);
        write("fill.frag", FRAGMENT);
        write("lib/tint.glsl", "vec3 tint() { return vec3(1.0) }\n"); // the semicolon missing
        ShaderLibrary library = new ShaderLibrary(GL.context(), ShaderSources.directory(dir), true, Map.of());
        try (ShaderProgram broken = library.program("fill.vert", "fill.frag")) {
            ShaderException e = assertThrows(ShaderException.class, broken::use);
            assertTrue(e.getMessage().contains("tint.glsl"), e.getMessage());
        }
        write("lib/tint.glsl", "vec3 tint() { return vec3(1.0); }\n");
        try (ShaderProgram misspelt = library.program("fill.vert", "fill.frag")) {
            misspelt.vec4("uScal");
            ShaderException e = assertThrows(ShaderException.class, misspelt::use);
            assertTrue(e.getMessage().contains("'uScal'"), e.getMessage());
        }
    }

    /** Draws the program over a small target and returns the centre pixel's RGBA. */
    private static int[] draw(ShaderProgram program, Uniform.Vec4 scale, float s) {
        try (Framebuffer target = new Framebuffer(GL.context(), 8, 8, Format.RGBA8, null, Sampling.NEAREST_CLAMP);
             Mesh triangle = GlTestSupport.fullScreenTriangle(GL.context())) {
            target.bind();
            glClearColor(0, 0, 0, 0);
            glClear(GL_COLOR_BUFFER_BIT);
            program.use();
            scale.set(s, s, s, 1);
            triangle.draw(new DrawStats());
            Image image = target.read();
            return new int[] {image.channel(4, 4, 0), image.channel(4, 4, 1), image.channel(4, 4, 2), image.channel(4, 4, 3)};
        }
    }

    @Test
    void failedReloadKeepsTheOldProgramAndAFixedOneIsPickedUp() throws IOException {
        write("fill.vert", VERTEX);
        write("fill.frag", FRAGMENT);
        write("lib/tint.glsl", "vec3 tint() { return vec3(1.0, 0.0, 0.0); }\n");
        ShaderLibrary library = new ShaderLibrary(GL.context(), ShaderSources.directory(dir));

        try (ShaderProgram program = library.program("fill.vert", "fill.frag")) {
            Uniform.Vec4 scale = program.vec4("uScale");
            assertEquals(List.of(255, 0, 0, 255), List.of(boxed(draw(program, scale, 1))));
            int before = program.id();

            // 1. an edit that does not compile: reload throws, the old program stays and still draws red
            write("lib/tint.glsl", "// edited\nvec3 tint() { return vec3(0.0, 1.0, 0.0) }\n");
            ShaderException e = assertThrows(ShaderException.class, program::reload);
            assertTrue(e.getMessage().contains(dir.resolve("lib/tint.glsl").toString()), e.getMessage());
            List<String> errors = library.reloadAll();
            assertEquals(1, errors.size(), errors.toString());
            assertEquals(before, program.id());
            assertEquals(List.of(255, 0, 0, 255), List.of(boxed(draw(program, scale, 1))));

            // 2. an edit that removes a uniform the program uses: also refused
            write("fill.frag", FRAGMENT.replace("uScale", "uGain"));
            write("lib/tint.glsl", "vec3 tint() { return vec3(0.0, 1.0, 0.0); }\n");
            ShaderException missing = assertThrows(ShaderException.class, program::reload);
            assertTrue(missing.getMessage().contains("'uScale'"), missing.getMessage());
            assertEquals(List.of(255, 0, 0, 255), List.of(boxed(draw(program, scale, 1))));

            // 3. fixed: reload succeeds, draws green, and the uniform handle follows the new program
            write("fill.frag", FRAGMENT);
            assertEquals(List.of(), library.reloadAll());
            int[] green = draw(program, scale, 0.5f);
            assertEquals(0, green[0]);
            assertEquals(128, green[1], 1); // 0.5 · 255 = 127.5, rounded to 127 or 128 by the 8-bit target
            assertEquals(0, green[2]);
        }
        assertEquals(0, GL.context().objects().live(GlObjects.Kind.PROGRAM));
        assertEquals(0, GL.context().objects().live(GlObjects.Kind.SHADER));
    }

    @Test
    void closedProgramsAreNotReloaded() throws IOException {
        write("fill.vert", VERTEX);
        write("fill.frag", FRAGMENT);
        write("lib/tint.glsl", "vec3 tint() { return vec3(1.0); }\n");
        ShaderLibrary library = new ShaderLibrary(GL.context(), ShaderSources.directory(dir));
        library.program("fill.vert", "fill.frag").close();

        write("lib/tint.glsl", "broken\n");

        assertEquals(List.of(), library.reloadAll());
    }

    private static Integer[] boxed(int[] values) {
        return java.util.Arrays.stream(values).boxed().toArray(Integer[]::new);
    }
}

package org.openworld.engine.failure;

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
import org.openworld.engine.bench.SummaryFileException;
import org.openworld.engine.camera.CameraPathFormatException;
import org.openworld.engine.core.SystemOrderException;
import org.openworld.engine.gl.GlUnavailableException;
import org.openworld.engine.gl.ShaderException;
import org.openworld.engine.settings.SettingsException;
import org.openworld.engine.terrain.heights.HeightImportException;

/** Each error type's exit code and printed form, the codes the README promises, and no error type left out. */
class UserFacingTest {

    /** The repository root, seen from the engine module's folder, where the tests run. */
    private static final Path ROOT = Path.of("..");

    /** A class that extends an exception or error type, with whatever follows up to its opening brace. */
    private static final Pattern ERROR_CLASS =
            Pattern.compile("class (\\w+) extends \\w*(?:Exception|Error)\\b([^{]*)\\{");

    @Test
    void theCodesAreTheDocumentedNumbers() {
        assertEquals(0, ExitCode.OK.code());
        assertEquals(1, ExitCode.INTERNAL_FAILURE.code());
        assertEquals(2, ExitCode.USER_MISTAKE.code());
        assertEquals(3, ExitCode.NO_OPENGL.code());
    }

    @Test
    void mistakesInInputAreCode2AfterTheProgramsName() {
        List<UserFacing> mistakes = List.of(new SettingsException("unknown setting 'camera.fovv'"),
                new HeightImportException("h.png: 8-bit, expected 16-bit"),
                new SummaryFileException(Path.of("a/summary.json"), "not a benchmark summary", null));
        for (UserFacing mistake : mistakes) {
            assertEquals(ExitCode.USER_MISTAKE, mistake.exitCode(), mistake.getMessage());
            assertEquals("openworld: " + mistake.getMessage(), mistake.userMessage("openworld"));
        }
    }

    @Test
    void aCameraPathErrorStandsAloneBehindItsPlace() {
        UserFacing error = new CameraPathFormatException("x.path", 3, 9, "a number for pitch", "'abc'");
        assertEquals(ExitCode.USER_MISTAKE, error.exitCode());
        assertEquals("x.path:3:9: expected a number for pitch, found 'abc'", error.userMessage("openworld"));
    }

    @Test
    void noOpenGlIsCode3AndItsReportStandsAlone() {
        UserFacing error = new GlUnavailableException("No usable OpenGL. Tried:\n  - headless-egl: failed\n");
        assertEquals(ExitCode.NO_OPENGL, error.exitCode());
        assertEquals(error.getMessage(), error.userMessage("openworld"));
    }

    @Test
    void failuresInsideTheProgramAreCode1() {
        for (UserFacing failure : List.of(new ShaderException("shaders/sky/sky.frag:12: syntax error"),
                new SystemOrderException("cycle: a -> b -> a"))) {
            assertEquals(ExitCode.INTERNAL_FAILURE, failure.exitCode(), failure.getMessage());
            assertEquals("openworld: " + failure.getMessage(), failure.userMessage("openworld"));
        }
    }

    /** A new error type that forgot the interface would reach the user as a stack trace; this finds it first. */
    @Test
    void everyErrorTypeOfTheProjectIsUserFacing() throws IOException {
        List<String> found = new ArrayList<>();
        List<String> missing = new ArrayList<>();
        for (String module : List.of("engine", "demo")) {
            try (Stream<Path> files = Files.walk(ROOT.resolve(module).resolve("src/main/java"))) {
                for (Path file : files.filter(f -> f.toString().endsWith(".java")).toList()) {
                    Matcher m = ERROR_CLASS.matcher(Files.readString(file));
                    while (m.find()) {
                        found.add(m.group(1));
                        if (!m.group(2).contains("UserFacing")) {
                            missing.add(m.group(1));
                        }
                    }
                }
            }
        }
        assertTrue(found.containsAll(List.of("SettingsException", "GlUnavailableException", "UserError")),
                "the scan finds the error types: " + found);
        assertEquals(List.of(), missing, "error types that do not implement UserFacing");
    }
}

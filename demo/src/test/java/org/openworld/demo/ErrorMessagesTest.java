package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.failure.ExitCode;
import picocli.CommandLine;

/**
 * Every error is one clear line (docs/errors.md): the cases a hostile pass found unclear or answered with a stack trace,
 * each run as the user would, checking the useful part of the message, the exit code, and that no Java exception
 * reaches the user. The tests that name a rendering command carry the tag {@code gl}; none of them gets as far as
 * making a context except where it says so.
 */
class ErrorMessagesTest {

    private static final String ORBIT = "../assets/paths/orbit.path";

    @TempDir
    Path dir;

    @RegisterExtension
    final ConsoleCapture console = new ConsoleCapture();

    /** Runs the command line, checks a user's mistake: exit 2, the message, no exception, one line. */
    private void userMistake(String message, String... args) {
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute(args), console.stderr());
        String err = console.stderr();
        assertTrue(err.contains(message), err);
        assertFalse(err.contains("Exception") || err.contains("\tat "), "no Java exception: " + err);
        assertEquals(1, err.lines().count(), "one line: " + err);
    }

    @Test
    void aCameraBeyondTheRenderersReachIsRefusedWithTheLimit() {
        userMistake("'1e9,400,1e9,45,-10': x is 1e9 m, beyond the renderer's reach: expected -16777216 .. 16777216 m "
                + "(2^24 m from the origin, where the CPU's float positions are 1 m apart)", "shot", "--out",
                dir.resolve("x.png").toString(), "--camera", "1e9,400,1e9,45,-10");
    }

    @Test
    void anUnknownPresetNamesTheValidOnes() {
        userMistake("unknown preset 'fast': expected one of low, default, ultra, paper", "settings", "--preset", "fast");
    }

    @Test
    @Tag("gl")
    void atNotANumberIsRefusedWithThePathsTimes() {
        userMistake("--at NaN: expected a time in seconds, e.g. within the path's keys 0.0 .. ",
                "shot", "--out", dir.resolve("x.png").toString(), "--path", ORBIT, "--at", "NaN");
    }

    @Test
    @Tag("gl")
    void atWithoutAPathIsRefused() {
        userMistake("--at picks a moment of a camera path: give --path FILE with it",
                "shot", "--out", dir.resolve("x.png").toString(), "--at", "3");
    }

    @Test
    @Tag("gl")
    void aFrameCountThatOverflowsIsRefused() {
        userMistake("--warmup 1 and --frames 2147483647 make 2147483648 frames: at most 1000000 in all",
                "bench", "--path", ORBIT, "--out", dir.resolve("b").toString(), "--frames", "2147483647",
                "--warmup", "1");
    }

    @Test
    void aSeedOutOfRangeGivesTheRange() {
        userMistake("'2147483648': expected a whole number 0 .. 2147483647", "settings", "--seed", "2147483648");
    }

    @Test
    @Tag("gl")
    void aCameraFieldThatIsNotANumberIsNamed() {
        userMistake("'1,2,NaN,0,0': z is 'NaN', expected a number of metres (x,y,z,yaw,pitch, e.g. 0,120,400,0,-10)",
                "shot", "--out", dir.resolve("x.png").toString(), "--camera", "1,2,NaN,0,0");
    }

    @Test
    void aRendererSettingIsSaidNotToApplyToHeightmap() {
        userMistake("--set shadow.kernel: a setting of the renderer, which heightmap does not use",
                "heightmap", "--out", dir.resolve("h").toString(), "--set", "shadow.kernel=3");
    }

    @Test
    @Tag("gl")
    void badSummaryJsonSaysWhatIsWrongWithoutJavaNames() throws Exception {
        Path bad = dir.resolve("summary.json");
        Files.writeString(bad, "\"frames\": 3\n");
        userMistake(bad + ": not valid summary JSON: expected an object '{' but found a string at line 1 column 2",
                "bench", "--compare", bad.toString(), bad.toString());
        assertFalse(console.stderr().contains("java.") || console.stderr().contains("gson"), console.stderr());
    }

    @Test
    @Tag("gl")
    void aSizeTooLargeForMemoryIsRefusedWithTheEstimate() {
        userMistake("--size 16384x16384: the render targets need about 6.0 GiB",
                "shot", "--out", dir.resolve("x.png").toString(), "--size", "16384x16384");
        assertFalse(Files.exists(dir.resolve("x.png")));
    }

    @Test
    void aSizeOverTheOpenGlsLargestTargetIsRefused() {
        var e = org.junit.jupiter.api.Assertions.assertThrows(UserError.class, () -> new Size(9000, 600).checkSide(8192));
        assertEquals("--size 9000x600: this OpenGL's render targets are at most 8192 pixels a side "
                + "(GL_MAX_TEXTURE_SIZE, GL_MAX_RENDERBUFFER_SIZE)", e.getMessage());
    }

    @Test
    void aSettingsFileThatIsNotTextSaysSo() throws Exception {
        Path config = dir.resolve("latin1.settings");
        Files.write(config, "# caf\u00e9\n".getBytes(StandardCharsets.ISO_8859_1));
        userMistake("settings file " + config + " is not a text file: byte 0xe9 at offset 5",
                "settings", "--config", config.toString());
    }

    @Test
    void aMisspeltOptionIsOneLineWithoutTheUsage() {
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("settings", "--sed", "3"));
        assertTrue(console.stderr().startsWith("openworld: Unknown options: '--sed', '3'; did you mean --seed"),
                console.stderr());
        assertTrue(console.stderr().strip().endsWith("('openworld settings --help' lists the options)"),
                console.stderr());
        assertEquals(1, console.stderr().lines().count(), "the suggestion in the same line: " + console.stderr());
        assertFalse(console.stderr().contains("Usage:"), console.stderr());
    }

    @Test
    void aMisspeltCommandIsOneLineWithTheSuggestion() {
        userMistake("openworld: Unmatched arguments from index 0: 'shoot', '--out', 'x.png'; did you mean shot?",
                "shoot", "--out", "x.png");
    }

    @Test
    void aBugSaysWhatFailedAndAsksForAReportWithTheTraceOnlyUnderDev() {
        StringWriter text = new StringWriter();
        CommandLine cli = new CommandLine(new Main()).setErr(new PrintWriter(text, true));
        var bug = new IllegalStateException("tile 3 has no parent");
        assertEquals(ExitCode.INTERNAL_FAILURE.code(), Main.report(bug, cli, false));
        assertEquals("openworld: internal error, illegal state: tile 3 has no parent; this is a bug in OpenWorld: "
                + "please report it with the command line (--dev prints the stack trace)", text.toString().strip());

        text.getBuffer().setLength(0);
        assertEquals(ExitCode.INTERNAL_FAILURE.code(), Main.report(bug, cli, true));
        assertTrue(text.toString().contains("java.lang.IllegalStateException: tile 3 has no parent")
                && text.toString().contains("\tat "), "the stack trace under --dev: " + text);
    }

    @Test
    void everyCommandTakesTheDevThatTheBugReportAsksFor() {
        CommandLine cli = new CommandLine(new Main());
        List<String> without = cli.getSubcommands().entrySet().stream()
                .filter(c -> !c.getKey().equals("help") && c.getValue().getCommandSpec().findOption("--dev") == null)
                .map(java.util.Map.Entry::getKey).toList();
        assertEquals(List.of(), without, "commands that refuse --dev, which the internal error's line offers");
    }

    /** A forked JVM running the command line; its exit code and stderr. */
    private record Run(int code, String stderr) {
    }

    private static Run fork(List<String> jvm, boolean withoutDisplay, String... args) throws Exception {
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.addAll(jvm);
        command.addAll(List.of("-cp", System.getProperty("java.class.path"), Main.class.getName()));
        command.addAll(List.of(args));
        ProcessBuilder builder = new ProcessBuilder(command).redirectOutput(ProcessBuilder.Redirect.DISCARD);
        if (withoutDisplay) {
            builder.environment().remove("DISPLAY");
            builder.environment().remove("WAYLAND_DISPLAY");
        }
        Process process = builder.start();
        String err = new String(process.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(process.waitFor(2, TimeUnit.MINUTES), "the forked JVM ends");
        return new Run(process.exitValue(), err);
    }

    @Test
    void aWorldTooLargeForTheHeapSaysHowMuchWasTriedAndHowToGiveMore() throws Exception {
        Run run = fork(List.of("-Xmx64m"), false, "heightmap", "--out", dir.resolve("h").toString(),
                "--set", "terrain.size=8192");
        assertEquals(ExitCode.USER_MISTAKE.code(), run.code(), run.stderr());
        assertTrue(run.stderr().matches("(?s).*openworld: out of memory: the Java heap of 6\\d MiB is too small for "
                + "this world; give Java more \\(e\\.g\\. JAVA_OPTS=-Xmx8g \\./openworld \\.\\.\\.\\).*"),
                run.stderr());
        assertFalse(run.stderr().contains("OutOfMemoryError") || run.stderr().contains("\tat "), run.stderr());
    }

    @Test
    @Tag("gl")
    void theWindowWithoutADisplaySaysSoAndOffersTheHeadlessCommands() throws Exception {
        Run run = fork(List.of(), true, "run", "--size", "160x90");
        assertEquals(ExitCode.NO_OPENGL.code(), run.code(), run.stderr());
        assertTrue(run.stderr().startsWith("No display found for the window (neither DISPLAY nor WAYLAND_DISPLAY "
                + "is set)"), run.stderr());
        assertTrue(run.stderr().contains("'openworld shot' or 'openworld bench'")
                && run.stderr().contains("xvfb-run -a ./openworld"), run.stderr());
        assertFalse(run.stderr().contains("Mesa") || run.stderr().contains("Exception"), run.stderr());
    }
}

package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.gl.HeadlessChoice;

/**
 * {@code --gl} and {@code --gpu} as a user gives them: the mode and device used, and each mistake's one line. All
 * tagged {@code gl}: the mistakes are found before a context is made, but by rendering commands.
 */
@Tag("gl")
class HeadlessOptionsTest {

    @TempDir
    Path dir;

    @RegisterExtension
    final ConsoleCapture console = new ConsoleCapture();

    @Test
    void infoListsEveryHeadlessModeAndTheDevicesAndUsesTheForcedOne() {
        assertEquals(0, Main.execute("info", "--gl", "headless-egl"));
        String out = console.stdout();
        assertTrue(out.contains("context:   headless-egl\n"), out);
        for (String mode : HeadlessChoice.names().split(", ")) {
            assertTrue(out.contains("\n  " + mode), mode + " listed in: " + out);
        }
        assertTrue(out.contains("EGL devices (--gpu N):\n  0: "), out);
    }

    @Test
    void shotOnDeviceZeroUsesTheDeviceMode() {
        Path png = dir.resolve("x.png");
        assertEquals(0, Main.execute("shot", "--out", png.toString(), "--size", "64x36", "--gpu", "0"));
        assertTrue(Files.exists(png));
        assertTrue(console.stdout().contains("headless-egl-device"), console.stdout());
    }

    @Test
    void aDeviceNumberPastTheListIsOneLineAndExitTwo() {
        int past = HeadlessChoice.devices().size();
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("shot", "--out", dir.resolve("x.png").toString(),
                "--size", "64x36", "--gpu", Integer.toString(past)));
        assertTrue(console.stderr().contains("--gpu " + past + ": expected a device number 0 .. "), console.stderr());
        assertFalse(console.stderr().contains("Exception"), console.stderr());
    }

    @Test
    void anUnknownModeNamesTheModes() {
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("info", "--gl", "pbuffer"));
        assertTrue(console.stderr().contains("'pbuffer': expected one of " + HeadlessChoice.names()), console.stderr());
    }

    @Test
    void aDeviceGoesOnlyWithTheDeviceMode() {
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("info", "--gl", "headless-egl", "--gpu", "0"));
        assertTrue(console.stderr().contains("--gpu 0 picks an EGL device: it goes only with --gl headless-egl-device"),
                console.stderr());
    }

    @Test
    void aNegativeDeviceIsACommandLineError() {
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("info", "--gpu", "-1"));
        assertTrue(console.stderr().contains("'-1': expected a device number from 0"), console.stderr());
    }
}

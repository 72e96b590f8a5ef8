package org.openworld.engine.gl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.openworld.engine.gl.GlContext.Mode;

/**
 * The quick exit, without OpenGL: which contexts ask for it, and a process that ends through it exits with its own
 * code, its output flushed, its shutdown hooks skipped (the limit its Javadoc states).
 */
class ProcessExitTest {

    @Test
    void onlyNvidiasEglAsksForIt() {
        assertTrue(ProcessExit.skipsTeardown(Mode.HEADLESS_EGL, "NVIDIA Corporation"));
        assertTrue(ProcessExit.skipsTeardown(Mode.HEADLESS_EGL_DEVICE, "NVIDIA Corporation"));
        assertFalse(ProcessExit.skipsTeardown(Mode.HEADLESS_EGL, "Mesa"));
        assertFalse(ProcessExit.skipsTeardown(Mode.WINDOW, "NVIDIA Corporation"), "GLX, not EGL");
        assertFalse(ProcessExit.skipsTeardown(Mode.HEADLESS_X11, "NVIDIA Corporation"), "GLX, not EGL");
        assertFalse(ProcessExit.skipsTeardown(Mode.HEADLESS_EGL, null));
    }

    @Test
    void aQuickExitKeepsTheCodeAndTheOutputAndSkipsTheHooks() throws IOException, InterruptedException {
        Process process = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), QuickExitMain.class.getName())
                .redirectErrorStream(true)
                .start();
        assertTrue(process.waitFor(60, TimeUnit.SECONDS), "the process ended");
        String output = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(QuickExitMain.CODE, process.exitValue(), "the code given, not 0 nor a crash's: " + output);
        assertTrue(output.contains("written"), "what was printed before, unflushed, still comes out: " + output);
        assertFalse(output.contains("hook ran"), "libc's _exit runs no JVM shutdown hook: " + output);
    }

    /** A program that prints without a line end (not flushed), registers a hook, then ends through the quick exit. */
    static final class QuickExitMain {
        static final int CODE = 7;

        public static void main(String[] args) {
            Runtime.getRuntime().addShutdownHook(new Thread(() -> System.out.println("hook ran")));
            System.out.print(String.join(" ", List.of("all", "written")));
            ProcessExit.skipTeardown();
            ProcessExit.exit(CODE);
        }
    }
}

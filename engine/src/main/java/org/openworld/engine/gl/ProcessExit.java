package org.openworld.engine.gl;

import static org.lwjgl.system.MemoryUtil.NULL;

import org.lwjgl.system.JNI;
import org.lwjgl.system.MemoryStack;
import org.lwjgl.system.MemoryUtil;
import org.lwjgl.system.Platform;
import org.lwjgl.system.linux.DynamicLinkLoader;

/**
 * How the program ends: {@link System#exit}, except after an OpenGL context from NVIDIA's EGL, where the process ends
 * at once with libc's {@code _exit}, skipping the native libraries' teardown.
 *
 * <p>Why: on an NVIDIA H200 (driver 580, no X server, the glvnd loader) every command crashed as the Java runtime
 * shut down, after writing all it writes and after its context was released (exit 134: a SIGSEGV at a null address
 * in {@code libEGL_nvidia.so.0}, on a thread of the driver's own). {@code System.exit} ends in libc's {@code exit},
 * which runs every library's destructors, glvnd's libEGL's among them (it unloads its vendors there); the crash fits
 * the driver's thread running on into that teardown, though the reports cannot show it. {@code _exit} ends the
 * process without running them; the kernel stops that thread with the others. Before it, the Java side is already
 * done: files are closed by the commands, {@code System.out} and {@code System.err} are flushed here, and no
 * shutdown hook of ours is left registered.
 *
 * <p>Cost: nothing. Limits: only contexts whose {@code GL_VENDOR} is NVIDIA's and that EGL made (the two EGL
 * headless modes) ask for it, so Mesa and every window keep the ordinary exit; JVM shutdown hooks and
 * {@code deleteOnExit} do not run after such a context. Not yet verified on NVIDIA: the crash was read from its
 * reports, and this path is tested on Mesa only ({@code ProcessExitTest} ends a process through it).
 */
public final class ProcessExit {

    private static volatile boolean skipTeardown;

    private ProcessExit() {
    }

    /** Whether a context of this vendor, made this way, asks for the quick exit: NVIDIA's EGL. */
    static boolean skipsTeardown(GlContext.Mode mode, String vendor) {
        boolean egl = mode == GlContext.Mode.HEADLESS_EGL || mode == GlContext.Mode.HEADLESS_EGL_DEVICE;
        return egl && vendor != null && vendor.startsWith("NVIDIA");
    }

    /** A context was made: remembers whether the process must skip the libraries' teardown when it ends. */
    static void madeContext(GlContext.Mode mode, String vendor) {
        if (skipsTeardown(mode, vendor)) {
            skipTeardown = true;
        }
    }

    /** Asks for the quick exit whatever the contexts were (a test ends a process through it). */
    static void skipTeardown() {
        skipTeardown = true;
    }

    /**
     * Ends the process with {@code code}: at once through {@code _exit} after a context from NVIDIA's EGL on Linux,
     * else (or when libc's {@code _exit} is not found) through {@link System#exit}.
     */
    public static void exit(int code) {
        if (skipTeardown && Platform.get() == Platform.LINUX) {
            System.out.flush();
            System.err.flush();
            long quick;
            try (MemoryStack stack = MemoryStack.stackPush()) {
                // the handle NULL is RTLD_DEFAULT: every loaded library, libc among them
                quick = DynamicLinkLoader.ndlsym(NULL, MemoryUtil.memAddress(stack.ASCII("_exit")));
            }
            if (quick != NULL) {
                JNI.invokeV(code, quick);
            }
        }
        System.exit(code);
    }
}

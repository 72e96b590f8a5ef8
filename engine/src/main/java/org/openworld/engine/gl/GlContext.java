package org.openworld.engine.gl;

import static org.lwjgl.glfw.GLFW.*;
import static org.lwjgl.opengl.GL11C.*;
import static org.lwjgl.system.MemoryUtil.NULL;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.lwjgl.glfw.GLFWErrorCallback;
import org.lwjgl.opengl.GL;
import org.lwjgl.system.Configuration;
import org.lwjgl.system.FunctionProvider;
import org.lwjgl.system.MemoryStack;
import org.openworld.engine.failure.ExitCode;

/**
 * One OpenGL context, windowed or headless, and the one place that creates it: tests, {@code shot}, {@code bench},
 * {@code figures} and the interactive window all come through here.
 *
 * <p>Headless is tried in this order (docs/design.md, "Headless rendering"), or one mode alone when a
 * {@link HeadlessChoice} forces it:
 * <ol>
 *   <li>{@code headless-egl-device}: EGL's device platform ({@link EglDevice}), a surfaceless context on a GPU (or on
 *       Mesa's software device), with no display, no window system and no libGL: what a bare GPU server has;</li>
 *   <li>{@code headless-egl}: GLFW's null platform with an EGL context, no display needed (Mesa llvmpipe works);</li>
 *   <li>{@code headless-x11}: a hidden GLFW window on the X display in {@code DISPLAY} (Xvfb, say).</li>
 * </ol>
 * A headless context renders into framebuffer objects, never into a default framebuffer (the device mode has none).
 *
 * <p>OpenGL's functions are loaded for each new context from that context's own API: {@code eglGetProcAddress} for
 * the two EGL modes, LWJGL's default (libGL's GLX, else EGL) for a window or a hidden X11 window ({@link #loadGl}).
 *
 * <p>A window needs a display: without one ({@code DISPLAY} and {@code WAYLAND_DISPLAY} unset, or GLFW unable to open
 * it) the error says "no display found" and offers the headless commands and {@code xvfb-run}; the advice to install
 * Mesa is kept for a display without a usable OpenGL.
 *
 * <p>We ask for OpenGL 4.5 core and accept 3.3 core, the floor every technique here is written for. With
 * {@code debug} ({@code --dev}) the context is a debug context ({@code GLFW_OPENGL_DEBUG_CONTEXT}, which GLFW passes
 * on to EGL as well; {@code EGL_CONTEXT_OPENGL_DEBUG} on a device) and every driver message is printed on stderr
 * through {@link GlDebug#printMessages}.
 */
public final class GlContext implements AutoCloseable {

    /** How the context was made; {@code openworld info} prints it. */
    public enum Mode {
        WINDOW("window", "a window"),
        HEADLESS_EGL_DEVICE("headless-egl-device", "EGL device platform, surfaceless"),
        HEADLESS_EGL("headless-egl", "GLFW null platform + EGL"),
        HEADLESS_X11("headless-x11", "hidden window on DISPLAY");

        private final String label;
        private final String how;

        Mode(String label, String how) {
            this.label = label;
            this.how = how;
        }

        /** The headless modes, in the order they are tried. */
        public static List<Mode> headless() {
            return List.of(HEADLESS_EGL_DEVICE, HEADLESS_EGL, HEADLESS_X11);
        }

        /** How the mode makes its context, in a few words. */
        public String how() {
            return how;
        }

        @Override
        public String toString() {
            return label;
        }
    }

    /** Versions we ask for, best first. */
    static final int[][] VERSIONS = {{4, 5}, {3, 3}};

    private static final String INSTALL_HINT = """
            OpenGL 3.3 core or newer is needed. On Debian or Ubuntu without a GPU, install Mesa's software renderer:
                sudo apt-get install -y libegl1 libegl-mesa0 libgl1-mesa-dri
            On a machine with a GPU, install its vendor driver and the glvnd loader (libegl1). For a hidden window
            instead of EGL, run under an X server, for example: xvfb-run -a ./openworld ...""";

    private static final String NO_DISPLAY = "No display found for the window";
    private static final String NO_DISPLAY_HINT = "render without one with 'openworld shot' or 'openworld bench', "
            + "or run the window on a virtual display: xvfb-run -a ./openworld";

    private final long window;
    private final Mode mode;
    private final String device;
    private final Runnable release;
    private final GlObjects objects = new GlObjects();
    private final TextureMemory textureMemory = new TextureMemory();
    private final GlDebug debug;
    private List<String> tried = List.of();

    /**
     * Takes a context already current on this thread.
     *
     * @param window    its GLFW window, or {@code NULL} for a device context
     * @param functions where OpenGL's functions come from, or {@code null} for LWJGL's default
     * @param release   what frees the context and whatever made it
     */
    GlContext(long window, Mode mode, String device, FunctionProvider functions, Runnable release) {
        this.window = window;
        this.mode = mode;
        this.device = device;
        this.release = release;
        loadGl(functions);
        GL.createCapabilities();
        this.debug = new GlDebug();
        ProcessExit.madeContext(mode, vendor());
    }

    /**
     * Loads OpenGL's entry points for a new context. LWJGL keeps one set for the process, so an EGL context
     * (functions from EGL) and an X11 one after it (libGL's) each load their own; LWJGL's loading at first use is
     * off, since on a bare GPU server there is no libGL for it to find.
     */
    private static void loadGl(FunctionProvider functions) {
        Configuration.OPENGL_EXPLICIT_INIT.set(true);
        GL.destroy();
        if (functions == null) {
            GL.create();
        } else {
            GL.create(functions);
        }
    }

    /** A headless context: every headless mode in order, the first that works. */
    public static GlContext headless() {
        return headless(false);
    }

    /**
     * A headless context, as {@link #headless()}.
     *
     * @param debug a debug context, its driver messages printed on stderr ({@code --dev})
     */
    public static GlContext headless(boolean debug) {
        return headless(HeadlessChoice.any(debug));
    }

    /**
     * A headless context as the choice says: its modes in order, the first that works.
     *
     * @throws GlUnavailableException saying what every mode said: exit code 3 when none works, 2 when a forced mode
     *                                or device is not on this machine
     */
    public static GlContext headless(HeadlessChoice choice) {
        List<String> tried = new ArrayList<>();
        for (Mode m : choice.modes()) {
            Attempt attempt = attempt(m, choice);
            if (attempt.context != null) {
                attempt.context.tried = List.copyOf(tried);
                return attempt.context;
            }
            tried.add(m + " (" + m.how + "): " + attempt.failure);
        }
        if (choice.mode() == null) {
            throw unavailable(tried);
        }
        StringBuilder message = new StringBuilder("headless mode " + choice.mode() + " is not available here. "
                + "What every headless mode said:\n");
        choice.survey().forEach(line -> message.append("  - ").append(line).append('\n'));
        throw new GlUnavailableException(message.toString().strip(), ExitCode.USER_MISTAKE);
    }

    /** One headless mode, as the choice says (its device, debug): the context, or why there is none. */
    static Attempt attempt(Mode m, HeadlessChoice choice) {
        return switch (m) {
            case HEADLESS_EGL_DEVICE -> EglDevice.attempt(choice);
            case HEADLESS_EGL -> tryCreate(m, GLFW_PLATFORM_NULL, 64, 64, false, null, choice.debug());
            case HEADLESS_X11 -> System.getenv("DISPLAY") == null
                    ? new Attempt(null, "skipped, DISPLAY is not set")
                    : tryCreate(m, GLFW_PLATFORM_X11, 64, 64, false, null, choice.debug());
            case WINDOW -> throw new IllegalArgumentException("a window is not a headless mode");
        };
    }

    /** A visible, resizable window with an OpenGL context. */
    public static GlContext window(String title, int width, int height, boolean vsync) {
        return window(title, width, height, vsync, false);
    }

    /**
     * A window, as {@link #window(String, int, int, boolean)}.
     *
     * @param debug a debug context, its driver messages printed on stderr ({@code --dev})
     */
    public static GlContext window(String title, int width, int height, boolean vsync, boolean debug) {
        if (displayServerUnset()) {
            throw new GlUnavailableException(NO_DISPLAY + " (neither DISPLAY nor WAYLAND_DISPLAY is set); "
                    + NO_DISPLAY_HINT);
        }
        Attempt attempt = tryCreate(Mode.WINDOW, GLFW_ANY_PLATFORM, width, height, true, title, debug);
        if (attempt.context == null) {
            if (noDisplay(attempt.failure)) {
                throw new GlUnavailableException(NO_DISPLAY + " (DISPLAY=" + System.getenv("DISPLAY")
                        + ", WAYLAND_DISPLAY=" + System.getenv("WAYLAND_DISPLAY") + ": " + attempt.failure + "); "
                        + NO_DISPLAY_HINT);
            }
            throw unavailable(List.of("window: " + attempt.failure));
        }
        glfwSwapInterval(vsync ? 1 : 0);
        return attempt.context;
    }

    /** A context, or why none was made. */
    record Attempt(GlContext context, String failure) {
    }

    private static Attempt tryCreate(Mode mode, int platform, int width, int height, boolean visible, String title,
                                     boolean debug) {
        List<String> errors = new ArrayList<>();
        GLFWErrorCallback callback = GLFWErrorCallback.create((code, description) ->
                errors.add(GLFWErrorCallback.getDescription(description)));
        GLFWErrorCallback previous = glfwSetErrorCallback(callback);
        if (previous != null) {
            previous.free();
        }
        if (platform != GLFW_ANY_PLATFORM && !glfwPlatformSupported(platform)) {
            return fail(callback, "this GLFW build does not support the platform");
        }
        glfwInitHint(GLFW_PLATFORM, platform);
        if (!glfwInit()) {
            return fail(callback, "glfwInit failed" + describe(errors));
        }
        for (int[] version : VERSIONS) {
            glfwDefaultWindowHints();
            glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
            glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, version[0]);
            glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, version[1]);
            glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
            glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
            glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
            glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
            glfwWindowHint(GLFW_DEPTH_BITS, 24);
            glfwWindowHint(GLFW_STENCIL_BITS, 8);
            glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug ? GLFW_TRUE : GLFW_FALSE);
            if (mode == Mode.HEADLESS_EGL) {
                glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
            }
            long window = glfwCreateWindow(width, height, title == null ? "OpenWorld" : title, NULL, NULL);
            if (window != NULL) {
                glfwMakeContextCurrent(window);
                // an EGL context takes its functions from EGL, as a device context does: no libGL needed
                FunctionProvider functions = mode == Mode.HEADLESS_EGL ? EglDevice.glFunctions() : null;
                GlContext context = new GlContext(window, mode, "", functions, () -> {
                    glfwDestroyWindow(window);
                    glfwTerminate();
                    if (mode == Mode.HEADLESS_EGL) {
                        EglDevice.releaseThread();
                    }
                    glfwSetErrorCallback(null);
                    callback.free();
                });
                String tooOld = context.tooOld(debug);
                return tooOld == null ? new Attempt(context, null) : new Attempt(null, tooOld);
            }
        }
        glfwTerminate();
        return fail(callback, "no OpenGL 4.5 or 3.3 core context" + describe(errors));
    }

    /**
     * Why this new context will not do (older than 3.3 core, and then closed), or {@code null} when it will; a debug
     * context starts printing its driver's messages here.
     */
    String tooOld(boolean debugContext) {
        if (versionAtLeast(3, 3)) {
            if (debugContext) {
                debug.printMessages(System.err::println);
            }
            return null;
        }
        String got = version();
        close();
        return "got OpenGL " + got + ", older than 3.3 core";
    }

    private static Attempt fail(GLFWErrorCallback callback, String why) {
        glfwSetErrorCallback(null);
        callback.free();
        return new Attempt(null, why);
    }

    /**
     * Whether this is a system whose windows need a display server (Linux, the BSDs) and none is named: neither
     * {@code DISPLAY} nor {@code WAYLAND_DISPLAY} is set. Checked before GLFW is asked, whose attempts would print
     * their own noise (libwayland's "XDG_RUNTIME_DIR is invalid") and end in "Failed to detect any supported
     * platform", which reads as a missing driver.
     */
    static boolean displayServerUnset() {
        String os = System.getProperty("os.name", "").toLowerCase(Locale.ROOT);
        return !os.contains("win") && !os.contains("mac")
                && System.getenv("DISPLAY") == null && System.getenv("WAYLAND_DISPLAY") == null;
    }

    /**
     * Whether GLFW's error says the display named in the environment could not be opened: GLFW connects to the
     * display server while it picks a platform, so "Failed to detect any supported platform" means no server
     * answered (X11 and Wayland both tried), before any OpenGL was asked for.
     */
    static boolean noDisplay(String failure) {
        String said = failure.toLowerCase(Locale.ROOT);
        return said.contains("failed to detect any supported platform") || said.contains("failed to open display")
                || said.contains("failed to connect to");
    }

    private static String describe(List<String> errors) {
        return errors.isEmpty() ? "" : " (" + String.join("; ", errors) + ")";
    }

    private static GlUnavailableException unavailable(List<String> tried) {
        StringBuilder message = new StringBuilder("No usable OpenGL. Tried:\n");
        tried.forEach(t -> message.append("  - ").append(t).append('\n'));
        return new GlUnavailableException(message.append(INSTALL_HINT).toString());
    }

    public Mode mode() {
        return mode;
    }

    /** The EGL device the context is on ({@code 0: software renderer (...)}), or empty outside the device mode. */
    public String device() {
        return device;
    }

    /** What each headless mode tried before this one said, in order; empty when the first worked. */
    public List<String> tried() {
        return tried;
    }

    /** The native GLFW window handle (invisible for headless contexts), or {@code NULL} for a device context. */
    public long window() {
        return window;
    }

    public GlObjects objects() {
        return objects;
    }

    /** The bytes this context's textures hold now and at most, counted by the engine for every driver. */
    public TextureMemory textureMemory() {
        return textureMemory;
    }

    /** Object labels, debug groups and driver messages ({@code KHR_debug}), no-ops where the driver lacks them. */
    public GlDebug debug() {
        return debug;
    }

    public String renderer() {
        return glGetString(GL_RENDERER);
    }

    public String vendor() {
        return glGetString(GL_VENDOR);
    }

    public String version() {
        return glGetString(GL_VERSION);
    }

    public boolean versionAtLeast(int major, int minor) {
        int[] v = new int[2];
        v[0] = glGetInteger(0x821B); // GL_MAJOR_VERSION
        v[1] = glGetInteger(0x821C); // GL_MINOR_VERSION
        return v[0] > major || (v[0] == major && v[1] >= minor);
    }

    /** The window's framebuffer size in pixels; 0×0 while minimised. */
    public int[] framebufferSize() {
        try (MemoryStack stack = MemoryStack.stackPush()) {
            var w = stack.mallocInt(1);
            var h = stack.mallocInt(1);
            glfwGetFramebufferSize(window, w, h);
            return new int[] {w.get(0), h.get(0)};
        }
    }

    public boolean shouldClose() {
        return glfwWindowShouldClose(window);
    }

    public void swapBuffers() {
        glfwSwapBuffers(window);
    }

    /** Destroys the window and ends GLFW, or releases the device's context; GL objects must have been closed before. */
    @Override
    public void close() {
        debug.close();
        GL.setCapabilities(null);
        release.run();
    }
}

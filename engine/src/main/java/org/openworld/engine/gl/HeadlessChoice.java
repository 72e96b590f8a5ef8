package org.openworld.engine.gl;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * Which headless context {@link GlContext#headless(HeadlessChoice)} makes: every headless mode in order until one
 * works, or one forced mode; on the EGL device platform, the first GPU or a chosen device.
 *
 * @param mode       the one mode to make, or {@code null} for every headless mode in order
 * @param device     the EGL device's number as {@code openworld info} lists it, or {@link #ANY_DEVICE}: a GPU before
 *                   a software renderer, the first that gives a context
 * @param debug      a debug context, its driver messages printed on stderr ({@code --dev})
 * @param glfwWindow the context must have a GLFW window (Dear ImGui's GLFW layer reads one, for {@code shot --ui}),
 *                   which leaves out the device mode
 */
public record HeadlessChoice(GlContext.Mode mode, int device, boolean debug, boolean glfwWindow) {

    /** No device asked for. */
    public static final int ANY_DEVICE = -1;

    /** Every headless mode in order, any device. */
    public static HeadlessChoice any(boolean debug) {
        return new HeadlessChoice(null, ANY_DEVICE, debug, false);
    }

    /** This choice, but only the one mode given. */
    public HeadlessChoice only(GlContext.Mode forced) {
        return new HeadlessChoice(forced, device, debug, glfwWindow);
    }

    /** The modes to try, in order: the device platform, GLFW's null platform with EGL, a hidden X11 window. */
    List<GlContext.Mode> modes() {
        if (mode != null) {
            return List.of(mode);
        }
        if (device != ANY_DEVICE) {
            return List.of(GlContext.Mode.HEADLESS_EGL_DEVICE);
        }
        return GlContext.Mode.headless().stream()
                .filter(m -> !(glfwWindow && m == GlContext.Mode.HEADLESS_EGL_DEVICE))
                .toList();
    }

    /**
     * The headless mode with this name ({@code headless-egl-device}, {@code headless-egl}, {@code headless-x11}).
     *
     * @throws IllegalArgumentException naming the headless modes there are
     */
    public static GlContext.Mode parseMode(String name) {
        return GlContext.Mode.headless().stream()
                .filter(m -> m.toString().equals(name.trim().toLowerCase(Locale.ROOT)))
                .findFirst()
                .orElseThrow(() -> new IllegalArgumentException("'" + name + "': expected one of "
                        + names()));
    }

    /** The headless modes' names, comma-separated, for messages and help. */
    public static String names() {
        return GlContext.Mode.headless().stream().map(Object::toString).collect(Collectors.joining(", "));
    }

    /**
     * Every headless mode tried on its own, each context closed at once: one line per mode with its renderer or why
     * it failed ({@code openworld info}).
     */
    public List<String> survey() {
        List<String> lines = new ArrayList<>();
        eachMode().forEach(one -> {
            GlContext.Mode m = one.mode();
            GlContext.Attempt attempt = GlContext.attempt(m, one);
            if (attempt.context() != null) {
                try (GlContext gl = attempt.context()) {
                    lines.add(m + ": works, " + gl.renderer() + ", OpenGL " + gl.version()
                            + (gl.device().isEmpty() ? "" : ", device " + gl.device()));
                }
            } else {
                lines.add(m + " (" + m.how() + "): " + attempt.failure());
            }
        });
        return lines;
    }

    /** The devices EGL's device platform lists here, as {@code --gpu} numbers them, or one line: why there are none. */
    public static List<String> devices() {
        try {
            return EglDevice.devices().stream().map(EglDevice.Device::toString).toList();
        } catch (IllegalStateException e) {
            return List.of("none: " + e.getMessage());
        }
    }

    /** Every headless mode, each forced on its own. */
    private Stream<HeadlessChoice> eachMode() {
        return GlContext.Mode.headless().stream().map(this::only);
    }
}

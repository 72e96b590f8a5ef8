package org.openworld.demo;

import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.HeadlessChoice;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Option;
import picocli.CommandLine.TypeConversionException;

/**
 * How a headless context is made: {@code --gl MODE} forces one headless mode, {@code --gpu N} picks an EGL device
 * (docs/design.md, "Headless rendering"). Without them every headless mode is tried in order.
 */
final class ContextOptions {

    @Option(names = "--gl", paramLabel = "MODE", converter = ModeConverter.class,
            description = "Make the headless context only this way: headless-egl-device, headless-egl or "
                    + "headless-x11 (default: each in that order, the first that works).")
    GlContext.Mode mode;

    @Option(names = "--gpu", paramLabel = "N", converter = DeviceConverter.class,
            description = "The EGL device to render on, numbered as 'openworld info' lists them (default: the first "
                    + "GPU, else Mesa's software device); the headless-egl-device mode.")
    Integer gpu;

    /**
     * The headless context these options ask for.
     *
     * @param glfwWindow the context must have a GLFW window (Dear ImGui's layer reads one)
     */
    HeadlessChoice choice(boolean debug, boolean glfwWindow) {
        if (gpu != null && mode != null && mode != GlContext.Mode.HEADLESS_EGL_DEVICE) {
            throw new UserError("--gpu " + gpu + " picks an EGL device: it goes only with --gl "
                    + GlContext.Mode.HEADLESS_EGL_DEVICE + ", not --gl " + mode);
        }
        if (glfwWindow && (gpu != null || mode == GlContext.Mode.HEADLESS_EGL_DEVICE)) {
            throw new UserError("--ui draws Dear ImGui through a GLFW window, which the "
                    + GlContext.Mode.HEADLESS_EGL_DEVICE + " mode has not: leave out --gpu and --gl "
                    + GlContext.Mode.HEADLESS_EGL_DEVICE);
        }
        return new HeadlessChoice(mode, gpu == null ? HeadlessChoice.ANY_DEVICE : gpu, debug, glfwWindow);
    }

    /** A headless mode by name, the names listed when it is none of them. */
    static final class ModeConverter implements ITypeConverter<GlContext.Mode> {
        @Override
        public GlContext.Mode convert(String text) {
            try {
                return HeadlessChoice.parseMode(text);
            } catch (IllegalArgumentException e) {
                throw new TypeConversionException(e.getMessage());
            }
        }
    }

    /** A device number: a whole number from 0. */
    static final class DeviceConverter implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String text) {
            try {
                int n = Integer.parseInt(text.trim());
                if (n >= 0) {
                    return n;
                }
            } catch (NumberFormatException e) {
                // the message below says what is valid
            }
            throw new TypeConversionException("'" + text + "': expected a device number from 0, as 'openworld info' "
                    + "lists the EGL devices");
        }
    }
}

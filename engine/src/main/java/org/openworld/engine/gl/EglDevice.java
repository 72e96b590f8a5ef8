package org.openworld.engine.gl;

import static org.lwjgl.egl.EGL10.*;
import static org.lwjgl.egl.EGL14.EGL_OPENGL_API;
import static org.lwjgl.egl.EGL12.eglBindAPI;
import static org.lwjgl.egl.EGL12.eglReleaseThread;
import static org.lwjgl.egl.EGL14.EGL_OPENGL_BIT;
import static org.lwjgl.egl.EGL15.*;
import static org.lwjgl.egl.EXTDeviceBase.eglQueryDeviceStringEXT;
import static org.lwjgl.egl.EXTDeviceBase.eglQueryDevicesEXT;
import static org.lwjgl.egl.EXTDeviceDRM.EGL_DRM_DEVICE_FILE_EXT;
import static org.lwjgl.egl.EXTPlatformBase.eglGetPlatformDisplayEXT;
import static org.lwjgl.egl.EXTPlatformDevice.EGL_PLATFORM_DEVICE_EXT;
import static org.lwjgl.system.MemoryUtil.NULL;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Collectors;
import org.lwjgl.PointerBuffer;
import org.lwjgl.egl.EGL;
import org.lwjgl.system.FunctionProvider;
import org.lwjgl.system.MemoryStack;
import org.openworld.engine.failure.ExitCode;

/**
 * A GPU as EGL's device platform lists it, and a surfaceless OpenGL context on it: the {@code headless-egl-device}
 * mode of {@link GlContext}, which needs no display, no window system and no libGL, only {@code libEGL.so.1} (the
 * glvnd loader) and a vendor's EGL behind it.
 *
 * <p>The calls, in order: {@code eglQueryDevicesEXT} lists the devices ({@code EGL_EXT_device_enumeration}, or
 * {@code EGL_EXT_device_base}, the older name that includes it: {@link #lacks});
 * {@code eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device)} opens one as a display
 * ({@code EGL_EXT_platform_device}); {@code eglCreateContext} makes an OpenGL 4.5 (else 3.3) core context, made
 * current on a 1×1 pbuffer, or with no surface at all ({@code EGL_KHR_surfaceless_context}) where the display makes
 * no pbuffer. Everything is drawn into the engine's own framebuffer objects; the pbuffer is there so that
 * framebuffer 0 is complete: a surfaceless context's framebuffer 0 is undefined, and any draw call made while it is
 * bound fails ({@code GL_INVALID_FRAMEBUFFER_OPERATION}), even one that rasterises nothing, such as the snow's
 * transform-feedback step. OpenGL's functions then come from {@code eglGetProcAddress} ({@link #glFunctions}), never
 * from libGL, which a bare GPU server need not have.
 *
 * <p>Who offers it: NVIDIA's proprietary driver (one device per GPU, the same on a server with no X), and Mesa
 * (a device per DRM render node for AMD and Intel, and its software device, llvmpipe, marked
 * {@code EGL_MESA_device_software}). Cost: opening a device and its context takes tens of milliseconds, once. Limit:
 * there is no window to show, so Dear ImGui's GLFW layer cannot run on it ({@code shot --ui} uses a GLFW mode).
 */
final class EglDevice implements AutoCloseable {

    /** Mesa's device extension for its software rasteriser: what tells llvmpipe from a GPU before any context. */
    private static final String SOFTWARE = "EGL_MESA_device_software";
    private static final String DRM = "EGL_EXT_device_drm";
    private static final String ENUMERATION = "EGL_EXT_device_enumeration";
    private static final String BASE = "EGL_EXT_device_base";
    private static final String PLATFORM = "EGL_EXT_platform_device";

    /** One device: its place in EGL's list, the handle, and what it says it is. */
    record Device(int index, long handle, String description, boolean software) {
        @Override
        public String toString() {
            return index + ": " + description;
        }
    }

    private final long display;
    private final long context;
    /** The 1×1 pbuffer the context is current on, or {@code EGL_NO_SURFACE} where the display gives none. */
    private final long surface;

    private EglDevice(long display, long context, long surface) {
        this.display = display;
        this.context = context;
        this.surface = surface;
    }

    /**
     * The devices EGL lists, in its order.
     *
     * @throws IllegalStateException naming what is missing: libEGL, or the client extensions the mode needs
     */
    static List<Device> devices() {
        String lacks = lacks(clientExtensions());
        if (lacks != null) {
            throw new IllegalStateException(lacks);
        }
        try (MemoryStack stack = MemoryStack.stackPush()) {
            var count = stack.mallocInt(1);
            if (!eglQueryDevicesEXT(null, count) || count.get(0) == 0) {
                throw new IllegalStateException("EGL lists no devices (is a driver installed?)");
            }
            PointerBuffer handles = stack.mallocPointer(count.get(0));
            eglQueryDevicesEXT(handles, count);
            List<Device> devices = new ArrayList<>();
            for (int i = 0; i < count.get(0); i++) {
                devices.add(describe(i, handles.get(i)));
            }
            return devices;
        }
    }

    /**
     * What the device mode needs of EGL's client extensions, or {@code null} when it has it: a way to list the
     * devices, {@code EGL_EXT_device_enumeration} or the older {@code EGL_EXT_device_base} (which the Khronos registry
     * defines as enumeration and query together, and which drivers still advertise), and
     * {@code EGL_EXT_platform_device} to open one as a display. The answer names exactly what is missing and lists
     * what the EGL did report, so that a driver that words it differently can be told from one that lacks it.
     *
     * @param clientExtensions {@code eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS)}, space-separated
     */
    static String lacks(String clientExtensions) {
        List<String> client = clientExtensions == null ? List.of()
                : List.of(clientExtensions.trim().split("\\s+"));
        List<String> missing = new ArrayList<>();
        if (!client.contains(ENUMERATION) && !client.contains(BASE)) {
            missing.add(ENUMERATION + " (or " + BASE + ")");
        }
        if (!client.contains(PLATFORM)) {
            missing.add(PLATFORM);
        }
        if (missing.isEmpty()) {
            return null;
        }
        String reported = clientExtensions == null || clientExtensions.isBlank() ? "none"
                : String.join(" ", client);
        return "this EGL lacks " + String.join(" and ", missing) + "; its client extensions: " + reported;
    }

    /**
     * EGL's client extensions ({@code eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS)}), which LWJGL's client
     * capabilities do not parse.
     */
    private static String clientExtensions() {
        try {
            return eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        } catch (LinkageError | RuntimeException e) {
            throw new IllegalStateException("libEGL could not be loaded (" + e.getMessage() + ")");
        }
    }

    private static Device describe(int index, long handle) {
        String extensions = String.valueOf(eglQueryDeviceStringEXT(handle, EGL_EXTENSIONS));
        boolean software = extensions.contains(SOFTWARE);
        String what = software ? "software renderer (" + SOFTWARE + ")"
                : extensions.contains(DRM) ? "GPU " + eglQueryDeviceStringEXT(handle, EGL_DRM_DEVICE_FILE_EXT)
                : "GPU";
        return new Device(index, handle, what, software);
    }

    /** The device mode: the chosen device, else each device in order, GPUs before a software renderer. */
    static GlContext.Attempt attempt(HeadlessChoice choice) {
        List<Device> devices;
        try {
            devices = devices();
        } catch (IllegalStateException e) {
            return new GlContext.Attempt(null, e.getMessage());
        }
        List<Device> order;
        if (choice.device() == HeadlessChoice.ANY_DEVICE) {
            order = devices.stream().sorted(Comparator.comparing(Device::software)).toList();
        } else if (choice.device() >= 0 && choice.device() < devices.size()) {
            order = List.of(devices.get(choice.device()));
        } else {
            String listed = devices.stream().map(Device::toString).collect(Collectors.joining(", "));
            throw new GlUnavailableException("--gpu " + choice.device() + ": expected a device number 0 .. "
                    + (devices.size() - 1) + "; EGL lists " + listed, ExitCode.USER_MISTAKE);
        }
        List<String> failures = new ArrayList<>();
        for (Device d : order) {
            try {
                EglDevice egl = open(d, choice.debug());
                GlContext context;
                try {
                    context = new GlContext(NULL, GlContext.Mode.HEADLESS_EGL_DEVICE, d.toString(), glFunctions(),
                            egl::close);
                } catch (RuntimeException e) { // OpenGL's functions not found through EGL
                    egl.close();
                    throw new IllegalStateException("OpenGL through eglGetProcAddress: " + e.getMessage(), e);
                }
                String tooOld = context.tooOld(choice.debug());
                if (tooOld == null) {
                    return new GlContext.Attempt(context, null);
                }
                failures.add("device " + d + ": " + tooOld);
            } catch (IllegalStateException e) {
                failures.add("device " + d + ": " + e.getMessage());
            }
        }
        return new GlContext.Attempt(null, String.join("; ", failures));
    }

    /**
     * A current OpenGL core context on the device: 4.5 if the driver gives it, else 3.3.
     *
     * @throws IllegalStateException saying which step failed, with EGL's error code
     */
    static EglDevice open(Device device, boolean debug) {
        long display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device.handle(), (int[]) null);
        if (display == EGL_NO_DISPLAY) {
            throw failed("eglGetPlatformDisplayEXT");
        }
        try (MemoryStack stack = MemoryStack.stackPush()) {
            if (!eglInitialize(display, stack.mallocInt(1), stack.mallocInt(1))) {
                throw failed("eglInitialize");
            }
            if (!EGL.createDisplayCapabilities(display).EGL_KHR_surfaceless_context) {
                eglTerminate(display);
                throw new IllegalStateException("the device's display lacks EGL_KHR_surfaceless_context");
            }
            eglBindAPI(EGL_OPENGL_API);
            PointerBuffer config = stack.mallocPointer(1);
            var found = stack.mallocInt(1);
            int[] wanted = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
            if (!eglChooseConfig(display, stack.ints(wanted), config, found) || found.get(0) == 0) {
                eglTerminate(display);
                throw failed("eglChooseConfig (an OpenGL config)");
            }
            for (int[] version : GlContext.VERSIONS) {
                int[] attributes = {EGL_CONTEXT_MAJOR_VERSION, version[0], EGL_CONTEXT_MINOR_VERSION, version[1],
                        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                        EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE, EGL_NONE};
                long context = eglCreateContext(display, config.get(0), EGL_NO_CONTEXT, attributes);
                if (context != EGL_NO_CONTEXT) {
                    long surface = eglCreatePbufferSurface(display, config.get(0),
                            stack.ints(EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE));
                    if (!eglMakeCurrent(display, surface, surface, context)) {
                        if (surface != EGL_NO_SURFACE) {
                            eglDestroySurface(display, surface);
                        }
                        eglDestroyContext(display, context);
                        eglTerminate(display);
                        throw failed("eglMakeCurrent");
                    }
                    return new EglDevice(display, context, surface);
                }
            }
            eglTerminate(display);
            throw failed("eglCreateContext (OpenGL 4.5 or 3.3 core)");
        }
    }

    private static IllegalStateException failed(String call) {
        return new IllegalStateException(call + " failed, EGL error 0x" + Integer.toHexString(eglGetError()));
    }

    /**
     * OpenGL's functions as {@code eglGetProcAddress} gives them (through the EGL library's own symbols first),
     * wrapped so that LWJGL's {@code GL.destroy} does not unload the EGL library with it.
     */
    static FunctionProvider glFunctions() {
        FunctionProvider egl = EGL.getFunctionProvider();
        return egl::getFunctionAddress;
    }

    /**
     * Releases the context and the display, then this thread's EGL state; the device itself belongs to the driver.
     * In EGL's order: nothing current, the context destroyed, the display terminated, and {@link #releaseThread}.
     * The EGL library itself stays loaded: LWJGL's {@code EGL} loads it at first use and keeps it for the process's
     * life (nothing here calls {@code EGL.destroy}), so neither this nor GLFW's {@code glfwTerminate}, which closes
     * its own handle on it, can unload it under a driver thread.
     */
    @Override
    public void close() {
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (surface != EGL_NO_SURFACE) {
            eglDestroySurface(display, surface);
        }
        eglDestroyContext(display, context);
        eglTerminate(display);
        releaseThread();
    }

    /**
     * {@code eglReleaseThread}: frees the calling thread's EGL state (its current API, its last error), which
     * {@code eglTerminate} leaves alone. GLFW does not call it, so its EGL mode calls this after
     * {@code glfwTerminate}. Cost: one call. On NVIDIA it is part of the careful release tried against the driver's
     * crash at exit, not yet seen to matter there ({@link ProcessExit}).
     */
    static void releaseThread() {
        eglReleaseThread();
    }
}

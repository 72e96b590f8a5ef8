package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL43C.*;

import java.util.List;
import java.util.function.Consumer;
import org.lwjgl.opengl.GL;
import org.lwjgl.opengl.GLCapabilities;
import org.lwjgl.opengl.GLDebugMessageCallback;

/**
 * The context's {@code KHR_debug} (core since OpenGL 4.3, an extension before): names that GPU debuggers and
 * profilers (RenderDoc, Nsight, apitrace) show instead of bare numbers, and the driver's own messages.
 *
 * <ul>
 *   <li>{@link #label}: {@code glObjectLabel} names one object, in the style of the timer spans:
 *       {@code terrain.heights}, {@code water.reflection.color};</li>
 *   <li>{@link #pushGroup}/{@link #popGroup}: {@code glPushDebugGroup} brackets the calls of one span, labelled like
 *       it ({@code main.terrain}, {@code shadow0.terrain}, {@code update.particles}), so a capture reads as the
 *       engine's frame;</li>
 *   <li>{@link #printMessages}: {@code glDebugMessageCallback} hands each message (errors, undefined behaviour,
 *       performance warnings) as one line to a sink; {@code --dev} prints them on stderr. A debug context
 *       ({@code GLFW_OPENGL_DEBUG_CONTEXT}) makes the driver say more; messages are synchronous, so the line comes
 *       while the guilty call is on the stack.</li>
 * </ul>
 * Whether the context has the extension is decided once, when the context is made; without it every call here does
 * nothing. Labels and groups cost a driver call each, a few per system per pass: nothing beside the draws.
 */
public final class GlDebug {

    /** The longest label the driver takes, characters; longer ones are cut. */
    private final int maxLabel;
    private final boolean available;
    private GLDebugMessageCallback callback;
    /** Where messages go while they are printed; null otherwise. */
    private Consumer<String> sink;

    GlDebug() {
        GLCapabilities caps = GL.getCapabilities();
        this.available = caps.OpenGL43 || caps.GL_KHR_debug;
        this.maxLabel = available ? glGetInteger(GL_MAX_LABEL_LENGTH) : 0;
    }

    /** Whether this context has {@code KHR_debug}; if not, every method here is a no-op. */
    public boolean available() {
        return available;
    }

    /**
     * Names one GL object.
     *
     * @param identifier its namespace: {@code GL_TEXTURE}, {@code GL_FRAMEBUFFER}, {@code GL_BUFFER},
     *                   {@code GL_PROGRAM}, {@code GL_VERTEX_ARRAY}, {@code GL_QUERY}
     * @param name       the object's GL name
     */
    public void label(int identifier, int name, String label) {
        if (available && name != 0) {
            glObjectLabel(identifier, name, label.length() < maxLabel ? label : label.substring(0, maxLabel - 1));
        }
    }

    /** The label of one GL object, "" if it has none or the extension is missing. */
    public String labelOf(int identifier, int name) {
        return available ? glGetObjectLabel(identifier, name, maxLabel) : "";
    }

    /** Opens a group of calls named {@code label}; every push is closed by one {@link #popGroup()}. */
    public void pushGroup(String label) {
        if (available) {
            glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, label);
        }
    }

    public void popGroup() {
        if (available) {
            glPopDebugGroup();
        }
    }

    /**
     * Hands every driver message of low severity or above to {@code sink} as one line, e.g.
     * {@code GL error (api, high, id 1282): GL_INVALID_OPERATION in glBindTexture(...)}; notifications (the driver
     * saying where a buffer lives) and the engine's own group markers are left out. So are the shader compiler's:
     * their source numbers and lines are those of the expanded text, so {@link ShaderProgram} hands them over itself,
     * mapped back to their files ({@link #compilerMessages}). {@code null} stops the output.
     */
    public void printMessages(Consumer<String> sink) {
        if (!available) {
            return;
        }
        this.sink = sink;
        if (sink == null) {
            glDisable(GL_DEBUG_OUTPUT);
            glDebugMessageCallback(null, 0);
            freeCallback();
            return;
        }
        GLDebugMessageCallback fresh = GLDebugMessageCallback.create((source, type, id, severity, length, message,
                user) -> sink.accept(line(source, type, id, severity, GLDebugMessageCallback.getMessage(length,
                message))));
        glDebugMessageCallback(fresh, 0);
        freeCallback();
        callback = fresh;
        glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_NOTIFICATION, (int[]) null, false);
        glDebugMessageControl(GL_DEBUG_SOURCE_SHADER_COMPILER, GL_DONT_CARE, GL_DONT_CARE, (int[]) null, false);
        glEnable(GL_DEBUG_OUTPUT);
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    }

    /**
     * The log of a shader that compiled, its lines already mapped to their files ({@code ShaderLog}), to the sink
     * while messages are printed: the compiler's warnings, in place of its own debug messages, which name the
     * expanded text's lines. A driver that takes the program from its shader cache (Mesa's) compiles nothing and
     * has no warnings to give.
     */
    void compilerMessages(List<String> mapped) {
        if (sink != null) {
            mapped.forEach(line -> sink.accept("GL shader compiler: " + line));
        }
    }

    /** One message as one line: {@code GL <type> (<source>, <severity>, id <id>): <message>}. */
    static String line(int source, int type, int id, int severity, String message) {
        return "GL " + typeName(type) + " (" + sourceName(source) + ", " + severityName(severity) + ", id " + id + "): "
                + message.strip();
    }

    private static String sourceName(int source) {
        return switch (source) {
            case GL_DEBUG_SOURCE_API -> "api";
            case GL_DEBUG_SOURCE_WINDOW_SYSTEM -> "window system";
            case GL_DEBUG_SOURCE_SHADER_COMPILER -> "shader compiler";
            case GL_DEBUG_SOURCE_THIRD_PARTY -> "third party";
            case GL_DEBUG_SOURCE_APPLICATION -> "application";
            default -> "other source";
        };
    }

    private static String typeName(int type) {
        return switch (type) {
            case GL_DEBUG_TYPE_ERROR -> "error";
            case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR -> "deprecated behaviour";
            case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR -> "undefined behaviour";
            case GL_DEBUG_TYPE_PORTABILITY -> "portability";
            case GL_DEBUG_TYPE_PERFORMANCE -> "performance";
            case GL_DEBUG_TYPE_MARKER -> "marker";
            case GL_DEBUG_TYPE_PUSH_GROUP -> "push group";
            case GL_DEBUG_TYPE_POP_GROUP -> "pop group";
            default -> "message";
        };
    }

    private static String severityName(int severity) {
        return switch (severity) {
            case GL_DEBUG_SEVERITY_HIGH -> "high";
            case GL_DEBUG_SEVERITY_MEDIUM -> "medium";
            case GL_DEBUG_SEVERITY_LOW -> "low";
            default -> "notification";
        };
    }

    /** Stops the output and frees the callback; the context calls it before it is destroyed. */
    void close() {
        printMessages(null);
    }

    private void freeCallback() {
        if (callback != null) {
            callback.free();
            callback = null;
        }
    }
}

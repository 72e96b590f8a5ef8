package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL20C.*;
import static org.lwjgl.opengl.GL30C.GL_INTERLEAVED_ATTRIBS;
import static org.lwjgl.opengl.GL30C.glTransformFeedbackVaryings;
import static org.lwjgl.opengl.GL31C.GL_INVALID_INDEX;
import static org.lwjgl.opengl.GL31C.glGetUniformBlockIndex;
import static org.lwjgl.opengl.GL31C.glUniformBlockBinding;
import static org.lwjgl.opengl.GL32C.GL_GEOMETRY_SHADER;
import static org.lwjgl.opengl.GL43C.GL_PROGRAM;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/**
 * A linked GLSL program built from stage files in {@code shaders/} (the stage comes from the extension:
 * {@code .vert}, {@code .frag}, {@code .geom}). Includes are expanded by {@link ShaderPreprocessor}. A compile
 * error is one paragraph: the program, the stage file and what it includes, then every line of the driver's log
 * rewritten by {@link ShaderLog} to the file and line it is about ({@code shaders/common/fog.glsl:15:24: error: ...});
 * a link error names the stages being linked, then the linker's lines.
 *
 * <p>Uniforms are typed handles resolved at link time: {@code Uniform.Mat4 model = program.mat4("uModel")} fails,
 * naming the program, when the uniform does not exist (or the compiler removed it as unused).
 *
 * <p>A program of a library that compiles on first use ({@link ShaderLibrary#ShaderLibrary(GlContext, ShaderSources,
 * boolean, java.util.Map)}, the engine's) is compiled and linked by its first {@link #use()}: a variant no frame draws (another
 * tiling, the shadowed light with no shadow system) costs nothing. Until then its uniform handles wait and the values
 * set on them are kept, in order, for the link; an error (a compile error, a missing uniform) comes at that first
 * use, naming the program as at start-up. If the
 * program declares a {@link SharedBlock} (the frame's, the shadow's), it is bound to its binding point; samplers named
 * like a {@link SharedTexture} are set to its unit.
 *
 * <p>{@link #reload()} rebuilds from the current sources (dev mode, F5): on failure the old program stays in use and
 * the error is thrown for the caller to print.
 */
public final class ShaderProgram implements Labelled {

    private final GlContext gl;
    private final ShaderSources sources;
    private final List<String> stages;
    private final List<String> captured;
    private final List<String> defines;
    private final List<Uniform> uniforms = new ArrayList<>();
    private final Consumer<ShaderProgram> onClose;
    /** Uniform values set before the first use, written in order once the program links. */
    private final List<Runnable> deferred = new ArrayList<>();
    private int id;
    private boolean closed;
    private String label;

    private ShaderProgram(GlContext gl, ShaderSources sources, List<String> stages, List<String> captured,
                          List<String> defines, boolean onFirstUse, Consumer<ShaderProgram> onClose) {
        this.gl = gl;
        this.sources = sources;
        this.stages = List.copyOf(stages);
        this.captured = List.copyOf(captured);
        this.defines = List.copyOf(defines);
        this.onClose = onClose;
        this.id = onFirstUse ? 0 : link();
    }

    /**
     * Compiles and links stage files; systems get programs from {@link ShaderLibrary#program}.
     *
     * @param captured the outputs transform feedback records, interleaved in this order (empty: none)
     * @param defines  names defined at the top of every stage (empty: none)
     * @param onFirstUse compile and link at the first {@link #use()}, not now
     */
    static ShaderProgram build(GlContext gl, ShaderSources sources, List<String> stageFiles, List<String> captured,
                               List<String> defines, boolean onFirstUse, Consumer<ShaderProgram> onClose) {
        return new ShaderProgram(gl, sources, stageFiles, captured, defines, onFirstUse, onClose);
    }

    /** Binds the program, compiling and linking it first if this is its first use. */
    public void use() {
        if (id == 0) {
            linkNow();
        }
        glUseProgram(id);
    }

    /** The GL name, linking first if the program has not been used yet. */
    public int id() {
        if (id == 0) {
            linkNow();
        }
        return id;
    }

    /** Whether the program is compiled and linked (else its first use does it). */
    boolean isLinked() {
        return id != 0;
    }

    /** Keeps a uniform's value, set before the program linked, for the link. */
    void defer(Runnable write) {
        deferred.add(write);
    }

    private void linkNow() {
        if (closed) {
            throw new IllegalStateException(this + " is closed");
        }
        int fresh = link();
        try {
            for (Uniform uniform : uniforms) {
                uniform.location = location(fresh, uniform.name);
            }
        } catch (ShaderException e) {
            deleteProgram(fresh);
            throw e;
        }
        id = fresh;
        if (label != null) {
            label(label);
        }
        glUseProgram(id);
        deferred.forEach(Runnable::run);
        deferred.clear();
    }

    public Uniform.Mat3 mat3(String name) {
        return resolve(new Uniform.Mat3(name));
    }

    public Uniform.Mat4 mat4(String name) {
        return resolve(new Uniform.Mat4(name));
    }

    public Uniform.Vec2 vec2(String name) {
        return resolve(new Uniform.Vec2(name));
    }

    public Uniform.Vec3 vec3(String name) {
        return resolve(new Uniform.Vec3(name));
    }

    public Uniform.Vec4 vec4(String name) {
        return resolve(new Uniform.Vec4(name));
    }

    public Uniform.Float float1(String name) {
        return resolve(new Uniform.Float(name));
    }

    public Uniform.Int int1(String name) {
        return resolve(new Uniform.Int(name));
    }

    /** A sampler uniform set once to its texture unit, handed out by {@link TextureUnits}. */
    public Uniform.Int sampler(TextureUnits.Sampler sampler) {
        return sampler(sampler.name(), sampler.unit());
    }

    /** A sampler uniform set once to its texture unit. */
    public Uniform.Int sampler(String name, int unit) {
        Uniform.Int sampler = int1(name);
        if (isLinked()) {
            use();
        }
        sampler.set(unit);
        return sampler;
    }

    private <U extends Uniform> U resolve(U uniform) {
        uniform.program = this;
        if (isLinked()) {
            uniform.location = location(id, uniform.name);
        }
        uniforms.add(uniform);
        return uniform;
    }

    private int location(int program, String name) {
        int location = glGetUniformLocation(program, name);
        if (location < 0) {
            throw new ShaderException(this + ": no active uniform '" + name
                    + "' (misspelt, or removed by the compiler because it does not affect the output)");
        }
        return location;
    }

    /**
     * Rebuilds the program from the current sources and re-resolves every uniform handle. If anything fails, the
     * old program stays and the error is thrown. A program not used yet has nothing to rebuild: its first use reads
     * the current sources.
     */
    public void reload() {
        if (!isLinked()) {
            return;
        }
        int fresh = link();
        try {
            int[] locations = new int[uniforms.size()];
            for (int i = 0; i < locations.length; i++) {
                locations[i] = location(fresh, uniforms.get(i).name);
            }
            for (int i = 0; i < locations.length; i++) {
                uniforms.get(i).location = locations[i];
            }
        } catch (ShaderException e) {
            deleteProgram(fresh);
            throw e;
        }
        deleteProgram(id);
        id = fresh;
        if (label != null) {
            label(label);
        }
    }

    /** The program's name, as {@link #label(String)} set it; null until then. */
    public String label() {
        return label;
    }

    /** Names the program; a {@link #reload()} names the rebuilt one the same. */
    @Override
    public void label(String name) {
        label = name;
        if (isLinked()) {
            gl.debug().label(GL_PROGRAM, id, name);
        }
    }

    private int link() {
        List<Integer> shaders = new ArrayList<>();
        try {
            for (String stage : stages) {
                shaders.add(compile(stage));
            }
            int program = glCreateProgram();
            gl.objects().created(GlObjects.Kind.PROGRAM);
            shaders.forEach(s -> glAttachShader(program, s));
            if (!captured.isEmpty()) {
                glTransformFeedbackVaryings(program, captured.toArray(CharSequence[]::new), GL_INTERLEAVED_ATTRIBS);
            }
            glLinkProgram(program);
            if (glGetProgrami(program, GL_LINK_STATUS) != GL_TRUE) {
                List<String> log = ShaderLog.link(glGetProgramInfoLog(program));
                deleteProgram(program);
                throw new ShaderException(report(this + ": linking " + linked() + " failed", log));
            }
            for (SharedBlock shared : SharedBlock.values()) {
                int block = glGetUniformBlockIndex(program, shared.block());
                if (block != GL_INVALID_INDEX) {
                    glUniformBlockBinding(program, block, shared.binding());
                }
            }
            glUseProgram(program);
            for (SharedTexture shared : SharedTexture.values()) {
                int location = glGetUniformLocation(program, shared.sampler());
                if (location >= 0) {
                    glUniform1i(location, shared.unit());
                }
            }
            return program;
        } finally {
            shaders.forEach(s -> {
                glDeleteShader(s);
                gl.objects().deleted(GlObjects.Kind.SHADER);
            });
        }
    }

    private int compile(String stage) {
        ShaderPreprocessor.Expanded expanded = new ShaderPreprocessor(sources).expand(stage, defines);
        int shader = glCreateShader(Stage.of(stage, sources).glType);
        gl.objects().created(GlObjects.Kind.SHADER);
        glShaderSource(shader, expanded.source());
        glCompileShader(shader);
        if (glGetShaderi(shader, GL_COMPILE_STATUS) != GL_TRUE) {
            List<String> log = ShaderLog.compile(glGetShaderInfoLog(shader), expanded, sources);
            glDeleteShader(shader);
            gl.objects().deleted(GlObjects.Kind.SHADER);
            List<String> includes = expanded.files().subList(1, expanded.files().size());
            String with = includes.isEmpty() ? ""
                    : " (with " + String.join(", ", includes.stream().map(sources::displayName).toList()) + ")";
            String heading = this + ": " + sources.displayName(stage) + with + " did not compile";
            throw new ShaderException(report(heading, log));
        }
        String warnings = glGetShaderInfoLog(shader);
        if (!warnings.isBlank()) {
            gl.debug().compilerMessages(ShaderLog.compile(warnings, expanded, sources));
        }
        return shader;
    }

    /** The stages being linked, e.g. "the vertex stage shaders/sky/sky.vert and the fragment stage ...". */
    private String linked() {
        return String.join(" and ", stages.stream()
                .map(stage -> "the " + Stage.of(stage, sources).word + " stage " + sources.displayName(stage))
                .toList());
    }

    /** A heading and the driver's lines under it, or a note that the driver said nothing. */
    private static String report(String heading, List<String> log) {
        return log.isEmpty() ? heading + " (the driver gave no log)" : heading + ":\n" + String.join("\n", log);
    }

    /** The stages a file can be, by its extension. */
    private enum Stage {
        VERTEX("vert", GL_VERTEX_SHADER, "vertex"),
        FRAGMENT("frag", GL_FRAGMENT_SHADER, "fragment"),
        GEOMETRY("geom", GL_GEOMETRY_SHADER, "geometry");

        private final String extension;
        private final int glType;
        private final String word;

        Stage(String extension, int glType, String word) {
            this.extension = extension;
            this.glType = glType;
            this.word = word;
        }

        static Stage of(String file, ShaderSources sources) {
            String extension = file.substring(file.lastIndexOf('.') + 1);
            for (Stage stage : values()) {
                if (stage.extension.equals(extension)) {
                    return stage;
                }
            }
            throw new ShaderException(sources.displayName(file) + ": unknown stage; use .vert, .frag or .geom");
        }
    }

    private void deleteProgram(int program) {
        glDeleteProgram(program);
        gl.objects().deleted(GlObjects.Kind.PROGRAM);
    }

    @Override
    public void close() {
        if (!closed) {
            closed = true;
            if (id != 0) {
                deleteProgram(id);
                id = 0;
            }
            onClose.accept(this);
        }
    }

    @Override
    public String toString() {
        return "program " + String.join("+", stages) + (defines.isEmpty() ? "" : " " + defines);
    }
}

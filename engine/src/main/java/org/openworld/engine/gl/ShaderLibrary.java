package org.openworld.engine.gl;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * Builds shader programs and keeps track of the live ones, so a dev-mode reload (F5) can rebuild every program
 * from the files on disk. A program that fails to reload keeps running its old code; the errors come back as text.
 */
public final class ShaderLibrary {

    private final GlContext gl;
    private final ShaderSources sources;
    private final List<ShaderProgram> live = new ArrayList<>();
    private final boolean onFirstUse;
    /** {@code NAME value} for each constant Java shares with every program. */
    private final List<String> constants = new ArrayList<>();

    /** A library whose programs compile when they are made, so an error comes at once; no shared constants. */
    public ShaderLibrary(GlContext gl, ShaderSources sources) {
        this(gl, sources, false, Map.of());
    }

    /**
     * @param onFirstUse compile each program at its first {@link ShaderProgram#use()} rather than when it is made (the
     *                   engine's: only the variants a frame draws are compiled)
     * @param constants  numbers defined in every program, {@code #define NAME value} (a double as a GLSL float)
     */
    public ShaderLibrary(GlContext gl, ShaderSources sources, boolean onFirstUse, Map<String, Number> constants) {
        this.gl = gl;
        this.sources = sources;
        this.onFirstUse = onFirstUse;
        constants.forEach((name, value) -> this.constants.add(name + " " + value));
    }

    /** Compiles and links stage files, e.g. {@code program("sky/sky.vert", "sky/sky.frag")}. */
    public ShaderProgram program(String... stageFiles) {
        return program(List.of(), stageFiles);
    }

    /**
     * A variant of a program: {@code #define NAME} for each of {@code defines} at the top of every stage, e.g.
     * {@code program(List.of("TERRAIN_FAR"), "terrain/terrain.vert", "terrain/terrain.frag")}.
     */
    public ShaderProgram program(List<String> defines, String... stageFiles) {
        return track(ShaderProgram.build(gl, sources, List.of(stageFiles), List.of(), with(defines), onFirstUse,
                live::remove));
    }

    /**
     * A vertex-only program for transform feedback: each vertex's {@code captured} outputs are written, interleaved
     * in this order, into the buffer bound to {@code GL_TRANSFORM_FEEDBACK_BUFFER} index 0 (draw it with
     * {@code GL_RASTERIZER_DISCARD} on: nothing is rasterised).
     */
    public ShaderProgram feedbackProgram(String vertexStage, String... captured) {
        if (!vertexStage.endsWith(".vert") || captured.length == 0) {
            throw new IllegalArgumentException("a feedback program is one .vert stage and at least one captured output");
        }
        return track(ShaderProgram.build(gl, sources, List.of(vertexStage), List.of(captured), with(List.of()),
                onFirstUse, live::remove));
    }

    /** The shared constants, then a variant's own defines. */
    private List<String> with(List<String> defines) {
        List<String> all = new ArrayList<>(constants);
        all.addAll(defines);
        return all;
    }

    private ShaderProgram track(ShaderProgram program) {
        live.add(program);
        return program;
    }

    /** The labels of the live programs ({@code system.role}), in the order they were made; null for unlabelled. */
    public List<String> labels() {
        return live.stream().map(ShaderProgram::label).toList();
    }

    public ShaderSources sources() {
        return sources;
    }

    /**
     * Rebuilds every live program from the current sources.
     *
     * @return one message per program that failed (it keeps its old code); empty when all reloaded
     */
    public List<String> reloadAll() {
        List<String> errors = new ArrayList<>();
        for (ShaderProgram program : List.copyOf(live)) {
            try {
                program.reload();
            } catch (ShaderException e) {
                errors.add(e.getMessage());
            }
        }
        return errors;
    }
}

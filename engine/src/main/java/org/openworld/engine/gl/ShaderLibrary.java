package org.openworld.engine.gl;

import java.util.ArrayList;
import java.util.List;

/**
 * Builds shader programs and keeps track of the live ones, so a dev-mode reload (F5) can rebuild every program
 * from the files on disk. A program that fails to reload keeps running its old code; the errors come back as text.
 */
public final class ShaderLibrary {

    private final GlContext gl;
    private final ShaderSources sources;
    private final List<ShaderProgram> live = new ArrayList<>();

    public ShaderLibrary(GlContext gl, ShaderSources sources) {
        this.gl = gl;
        this.sources = sources;
    }

    /** Compiles and links stage files, e.g. {@code program("sky/sky.vert", "sky/sky.frag")}. */
    public ShaderProgram program(String... stageFiles) {
        ShaderProgram program = ShaderProgram.build(gl, sources, stageFiles, live::remove);
        live.add(program);
        return program;
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

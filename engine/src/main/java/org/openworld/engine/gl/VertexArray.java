package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL30C.*;

/**
 * One vertex array object, for systems that lay out their own attributes (instanced patches, particles); a plain
 * indexed mesh uses {@link Mesh}, which owns one of these itself.
 */
public final class VertexArray implements AutoCloseable {

    private final GlContext gl;
    private int id;

    public VertexArray(GlContext gl) {
        this.gl = gl;
        this.id = glGenVertexArrays();
        gl.objects().created(GlObjects.Kind.VERTEX_ARRAY);
    }

    public void bind() {
        glBindVertexArray(id);
    }

    @Override
    public void close() {
        if (id != 0) {
            glDeleteVertexArrays(id);
            gl.objects().deleted(GlObjects.Kind.VERTEX_ARRAY);
            id = 0;
        }
    }
}

package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL30C.*;
import static org.lwjgl.opengl.GL43C.GL_VERTEX_ARRAY;

import org.lwjgl.opengl.GL30C;

/**
 * One vertex array object, for systems that lay out their own attributes (instanced patches, particles); a plain
 * indexed mesh uses {@link Mesh}, which owns one of these itself.
 */
public final class VertexArray implements Labelled {

    private final GlContext gl;
    private int id;

    public VertexArray(GlContext gl) {
        this.gl = gl;
        this.id = gl.objects().create(GlObjects.Kind.VERTEX_ARRAY, GL30C::glGenVertexArrays);
    }

    public void bind() {
        glBindVertexArray(id);
    }

    @Override
    public void label(String name) {
        gl.debug().label(GL_VERTEX_ARRAY, id, name);
    }

    @Override
    public void close() {
        id = gl.objects().delete(GlObjects.Kind.VERTEX_ARRAY, id, GL30C::glDeleteVertexArrays);
    }
}

package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL15C.*;
import static org.lwjgl.opengl.GL30C.GL_TRANSFORM_FEEDBACK_BUFFER;
import static org.lwjgl.opengl.GL30C.glBindBufferBase;
import static org.lwjgl.opengl.GL43C.GL_BUFFER;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import org.lwjgl.opengl.GL15C;

/** One GL buffer object: vertices, indices, uniforms or transform-feedback storage. */
public final class GpuBuffer implements Labelled {

    private final GlContext gl;
    private final int target;
    private int id;

    /**
     * @param target e.g. {@code GL_ARRAY_BUFFER}, {@code GL_ELEMENT_ARRAY_BUFFER}, {@code GL_UNIFORM_BUFFER}
     */
    public GpuBuffer(GlContext gl, int target) {
        this.gl = gl;
        this.target = target;
        this.id = gl.objects().create(GlObjects.Kind.BUFFER, GL15C::glGenBuffers);
    }

    public int id() {
        return id;
    }

    public void bind() {
        glBindBuffer(target, id);
    }

    /** Binds to an indexed binding point of its own target (a uniform buffer to a block's binding). */
    public void bindBase(int index) {
        glBindBufferBase(target, index, id);
    }

    /**
     * Binds as the store of transform feedback's output {@code index}, whatever its own target: a vertex buffer the
     * next step reads is written by this one.
     */
    public void bindForFeedback(int index) {
        glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, index, id);
    }

    /** Allocates and fills; {@code usage} e.g. {@code GL_STATIC_DRAW}. */
    public void upload(FloatBuffer data, int usage) {
        bind();
        glBufferData(target, data, usage);
    }

    public void upload(IntBuffer data, int usage) {
        bind();
        glBufferData(target, data, usage);
    }

    /** Allocates without data. */
    public void allocate(long bytes, int usage) {
        bind();
        glBufferData(target, bytes, usage);
    }

    /** Overwrites from the start; the buffer must be large enough. */
    public void update(ByteBuffer data) {
        bind();
        glBufferSubData(target, 0, data);
    }

    @Override
    public void label(String name) {
        gl.debug().label(GL_BUFFER, id, name);
    }

    @Override
    public void close() {
        id = gl.objects().delete(GlObjects.Kind.BUFFER, id, GL15C::glDeleteBuffers);
    }
}

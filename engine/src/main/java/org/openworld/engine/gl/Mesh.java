package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL30C.*;
import static org.lwjgl.opengl.GL31C.glDrawElementsInstanced;
import static org.lwjgl.opengl.GL33C.glVertexAttribDivisor;

import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import org.lwjgl.system.MemoryUtil;

/**
 * Indexed triangles in one vertex array: interleaved float attributes in one buffer, 32-bit indices in another.
 * Every draw goes through here so the frame's triangle and draw-call counts are exact.
 *
 * <p><b>Instancing.</b> The same triangles drawn many times in one call, each copy (instance) with its own
 * attributes: {@link #instances} points attributes at a {@link GpuBuffer} of per-instance records with a divisor of
 * 1 (the attribute advances once per instance, not per vertex), and {@link #drawInstances} draws a run of them with
 * {@code glDrawElementsInstanced}. GL 3.3 has no base instance, so a run that does not start at the first record is
 * drawn by moving the attribute pointers to it (a few cheap calls, made only when the start changes). One draw call
 * counts {@code triangles × instances} triangles. The trees and the snowflakes draw this way.
 */
public final class Mesh implements Labelled {

    /** One vertex attribute: its shader location and its number of floats. */
    public record Attribute(int location, int components) {
    }

    private final VertexArray vao;
    private final GpuBuffer vertices;
    private final GpuBuffer indices;
    private final int indexCount;
    /** Where the per-instance attributes come from, or null for a mesh never instanced. */
    private GpuBuffer instanceBuffer;
    private int instanceStride;
    private Attribute[] instanceLayout;
    /** The record the instance attributes point at now. */
    private long pointedAt;

    /**
     * @param interleaved vertex data, attributes in {@code layout} order for each vertex
     * @param triangles   three indices per triangle
     */
    public Mesh(GlContext gl, float[] interleaved, int[] triangles, Attribute... layout) {
        if (triangles.length % 3 != 0) {
            throw new IllegalArgumentException("index count " + triangles.length + " is not a multiple of 3");
        }
        this.indexCount = triangles.length;
        this.vao = new VertexArray(gl);
        vao.bind();
        vertices = new GpuBuffer(gl, GL_ARRAY_BUFFER);
        indices = new GpuBuffer(gl, GL_ELEMENT_ARRAY_BUFFER);
        FloatBuffer vertexData = MemoryUtil.memAllocFloat(interleaved.length).put(interleaved).flip();
        IntBuffer indexData = MemoryUtil.memAllocInt(triangles.length).put(triangles).flip();
        try {
            vertices.upload(vertexData, GL_STATIC_DRAW);
            indices.upload(indexData, GL_STATIC_DRAW);
        } finally {
            MemoryUtil.memFree(vertexData);
            MemoryUtil.memFree(indexData);
        }
        int stride = 0;
        for (Attribute a : layout) {
            stride += a.components() * Float.BYTES;
        }
        long offset = 0;
        for (Attribute a : layout) {
            glEnableVertexAttribArray(a.location());
            glVertexAttribPointer(a.location(), a.components(), GL_FLOAT, false, stride, offset);
            offset += (long) a.components() * Float.BYTES;
        }
        glBindVertexArray(0);
    }

    /**
     * One triangle covering the whole viewport, corners (−1, −1), (3, −1), (−1, 3) in clip space at attribute 0
     * (vec2): what full-screen passes (sky, water) draw, without the seam of two triangles.
     */
    public static Mesh fullScreenTriangle(GlContext gl) {
        return new Mesh(gl, new float[] {-1, -1, 3, -1, -1, 3}, new int[] {0, 1, 2}, new Attribute(0, 2));
    }

    public int triangleCount() {
        return indexCount / 3;
    }

    /**
     * Reads the per-instance attributes from {@code buffer} (an array buffer of records, one per instance), advancing
     * once per instance. Call again to switch buffers (the snow's two state buffers take turns); the buffer stays
     * owned by the caller.
     *
     * @param stride floats per record, at least the layout's sum: the layout is read from each record's start and
     *               the rest of the record is skipped
     * @param layout the attributes at the start of each record, in order; their locations must not be the
     *               vertices'
     */
    public void instances(GpuBuffer buffer, int stride, Attribute... layout) {
        int floats = 0;
        for (Attribute a : layout) {
            floats += a.components();
        }
        if (layout.length == 0 || floats > stride) {
            throw new IllegalArgumentException("an instance record of " + stride + " floats cannot hold attributes of "
                    + floats + " floats");
        }
        instanceBuffer = buffer;
        instanceStride = stride;
        instanceLayout = layout.clone();
        vao.bind();
        pointInstances(0);
        for (Attribute a : layout) {
            glEnableVertexAttribArray(a.location());
            glVertexAttribDivisor(a.location(), 1);
        }
        glBindVertexArray(0);
    }

    /** Points the instance attributes at record {@code first}; the vertex array must be bound. */
    private void pointInstances(long first) {
        glBindBuffer(GL_ARRAY_BUFFER, instanceBuffer.id());
        long offset = first * instanceStride * Float.BYTES;
        for (Attribute a : instanceLayout) {
            glVertexAttribPointer(a.location(), a.components(), GL_FLOAT, false, instanceStride * Float.BYTES, offset);
            offset += (long) a.components() * Float.BYTES;
        }
        pointedAt = first;
    }

    /**
     * Draws every triangle once for each of {@code count} instances, records {@code first} to
     * {@code first + count - 1} of the {@link #instances} buffer: one draw call, {@code triangles × count} triangles.
     */
    public void drawInstances(long first, int count, DrawStats stats) {
        if (instanceBuffer == null) {
            throw new IllegalStateException("drawInstances before instances(...): the mesh has no instance attributes");
        }
        if (count <= 0) {
            return;
        }
        vao.bind();
        if (first != pointedAt) {
            pointInstances(first);
        }
        glDrawElementsInstanced(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, 0, count);
        stats.add(1, (long) triangleCount() * count);
    }

    /** Draws every triangle once. */
    public void draw(DrawStats stats) {
        vao.bind();
        glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, 0);
        stats.add(1, triangleCount());
    }

    /** Names the vertex array, and its buffers {@code name.vertices} and {@code name.indices}. */
    @Override
    public void label(String name) {
        vao.label(name);
        vertices.label(name + ".vertices");
        indices.label(name + ".indices");
    }

    @Override
    public void close() {
        vertices.close();
        indices.close();
        vao.close();
    }
}

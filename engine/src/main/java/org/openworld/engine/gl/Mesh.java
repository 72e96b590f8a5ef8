package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL30C.*;

import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import org.lwjgl.system.MemoryUtil;

/**
 * Indexed triangles in one vertex array: interleaved float attributes in one buffer, 32-bit indices in another.
 * Every draw goes through here so the frame's triangle and draw-call counts are exact.
 */
public final class Mesh implements Labelled {

    /** One vertex attribute: its shader location and its number of floats. */
    public record Attribute(int location, int components) {
    }

    private final VertexArray vao;
    private final GpuBuffer vertices;
    private final GpuBuffer indices;
    private final int indexCount;

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

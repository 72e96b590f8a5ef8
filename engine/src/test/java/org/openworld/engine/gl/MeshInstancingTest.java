package org.openworld.engine.gl;

import org.openworld.engine.GlTest;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.lwjgl.opengl.GL11C.*;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_STATIC_DRAW;

import java.nio.FloatBuffer;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.HeadlessGl;

/**
 * {@link Mesh#drawInstances} on the real driver: a square one cell wide drawn once per record of an instance buffer,
 * each record a cell's offset plus a float the layout skips, over a row of {@link #CELLS} cells. Exactly the cells
 * of the drawn records are painted, and the draw counts as one call of {@code triangles × instances}.
 */
@GlTest
class MeshInstancingTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int CELLS = 8;
    /** Pixels per cell. */
    static final int CELL = 4;
    /** Floats per instance record: the offset (2) and one the layout does not read. */
    static final int STRIDE = 3;

    /** Record i moves the square from the first cell to cell i (clip units: 2 / CELLS per cell). */
    static FloatBuffer offsets() {
        FloatBuffer data = MemoryUtil.memAllocFloat(CELLS * STRIDE);
        for (int i = 0; i < CELLS; i++) {
            data.put(i * 2f / CELLS).put(0).put(-99);
        }
        return data.flip();
    }

    /** Draws records first .. first + count − 1 and returns which cells came out painted. */
    static boolean[] draw(long first, int count, DrawStats stats) {
        ShaderLibrary library = new ShaderLibrary(GL.context(), ShaderSources.classpath());
        float w = 2f / CELLS;
        FloatBuffer data = offsets();
        try (ShaderProgram program = library.program("test/instanced.vert", "test/solid.frag");
             Framebuffer target = new Framebuffer(GL.context(), CELLS * CELL, CELL, Format.RGBA8, null,
                     Sampling.NEAREST_CLAMP);
             GpuBuffer records = new GpuBuffer(GL.context(), GL_ARRAY_BUFFER);
             Mesh square = new Mesh(GL.context(), new float[] {-1, -1, -1 + w, -1, -1 + w, 1, -1, 1},
                     new int[] {0, 1, 2, 0, 2, 3}, new Mesh.Attribute(0, 2))) {
            records.upload(data, GL_STATIC_DRAW);
            square.instances(records, STRIDE, new Mesh.Attribute(1, 2));
            target.bind();
            glClearColor(0, 0, 0, 1);
            glClear(GL_COLOR_BUFFER_BIT);
            program.use();
            program.vec4("uColor").set(1, 1, 1, 1);
            square.drawInstances(first, count, stats);
            Image image = target.read();
            boolean[] painted = new boolean[CELLS];
            for (int c = 0; c < CELLS; c++) {
                painted[c] = image.channel(c * CELL + CELL / 2, CELL / 2, 0) > 128;
            }
            return painted;
        } finally {
            MemoryUtil.memFree(data);
        }
    }

    @Test
    void nInstancesDrawNCopiesAsOneCall() {
        DrawStats stats = new DrawStats();
        boolean[] painted = draw(0, 5, stats);
        for (int c = 0; c < CELLS; c++) {
            assertEquals(c < 5, painted[c], "cell " + c);
        }
        assertEquals(1, stats.drawCalls());
        assertEquals(2 * 5, stats.triangles());
    }

    @Test
    void aRunFromALaterRecordDrawsThoseRecordsOnly() {
        DrawStats stats = new DrawStats();
        boolean[] painted = draw(3, 4, stats);
        for (int c = 0; c < CELLS; c++) {
            assertEquals(c >= 3 && c < 7, painted[c], "cell " + c);
        }
        assertEquals(1, stats.drawCalls());
        assertEquals(2 * 4, stats.triangles());
    }

    @Test
    void aRecordTooShortForTheLayoutIsRefused() {
        try (Mesh square = Mesh.fullScreenTriangle(GL.context());
             GpuBuffer records = new GpuBuffer(GL.context(), GL_ARRAY_BUFFER)) {
            assertThrows(IllegalArgumentException.class,
                    () -> square.instances(records, 1, new Mesh.Attribute(1, 2)));
            assertThrows(IllegalStateException.class, () -> square.drawInstances(0, 1, new DrawStats()));
        }
    }
}

package org.openworld.engine.terrain.mesh;

import static org.lwjgl.opengl.GL33C.*;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.GpuBuffer;
import org.openworld.engine.gl.VertexArray;
import org.openworld.engine.terrain.lod.Corner;
import org.openworld.engine.terrain.lod.PatchList;
import org.openworld.engine.terrain.lod.Side;

/**
 * Draws a {@link PatchList} with one instanced draw call per index pattern in use, so the draw calls of a pass do not
 * grow with the number of visible patches (at most one interior pattern per stride and one per side and edge
 * stride: 29 for 65-vertex patches in quadtree mode, whatever the world size).
 *
 * <p>All patches share one vertex grid of (N+1)² (column, row) pairs and one element buffer holding every
 * {@link PatchPatterns} pattern. What differs per patch travels as instance attributes, written once per frame
 * into a streamed buffer, sorted by pattern (a stable counting sort) so each draw reads a contiguous run, and the
 * patches come in the order the caller gives (nearest first, so the depth test rejects hidden ground before it is
 * shaded):
 * <pre>
 *   location 1  ivec4  origin sample x, origin sample z, samples per grid step, level
 *   location 2  ivec4  side levels  (north, east, south, west)
 *   location 3  ivec4  corner levels (north-west, north-east, south-east, south-west)
 *   location 4  vec2   copy offset, metres
 *   location 5  float  morph factor k
 *   location 6  vec4   side neighbours' k (north, east, south, west)
 *   location 7  vec4   diagonal neighbours' k (north-west, north-east, south-east, south-west)
 * </pre>
 * GL 3.3 has no base instance, so each draw re-points the instance attributes at its run's offset.
 */
public final class PatchRenderer implements AutoCloseable {

    /** Bytes per instance: 12 ints and 11 floats. */
    private static final int STRIDE = 23 * 4;
    /** Instance attribute locations 1 .. 7. */
    private static final int LAST_INSTANCE_LOCATION = 7;
    /** Each patch is drawn by five patterns: its interior and its four edge strips. */
    private static final int PATTERNS_PER_PATCH = 5;
    /** The enum values, kept: {@code values()} copies its array on every call, and these loops run per patch. */
    private static final Side[] SIDES = Side.values();
    private static final Corner[] CORNERS = Corner.values();

    private final PatchPatterns patterns;
    private final GpuBuffer grid;
    private final GpuBuffer elements;
    private final GpuBuffer instances;
    private final VertexArray vao;
    private ByteBuffer staging;
    private final int[] runStart;
    private final int[] runLength;
    private final int[] cursor;
    private final int[] drawOrder;
    private int[] slotPattern = new int[0];

    /**
     * Makes the shared geometry, handed to the system's owner ({@code terrain.patches}, {@code terrain.patches.grid},
     * ...); the renderer itself holds only the staging memory, which {@link #close()} frees.
     */
    public PatchRenderer(EngineContext context, PatchPatterns patterns) {
        GlContext gl = context.gl();
        this.patterns = patterns;
        this.runStart = new int[patterns.patternCount()];
        this.runLength = new int[patterns.patternCount()];
        this.cursor = new int[patterns.patternCount()];
        this.drawOrder = new int[patterns.patternCount()];
        vao = context.own("patches", new VertexArray(gl));
        vao.bind();
        grid = context.own("patches.grid", new GpuBuffer(gl, GL_ARRAY_BUFFER));
        elements = context.own("patches.elements", new GpuBuffer(gl, GL_ELEMENT_ARRAY_BUFFER));
        instances = context.own("patches.instances", new GpuBuffer(gl, GL_ARRAY_BUFFER));
        uploadGrid(patterns.cells());
        IntBuffer indices = MemoryUtil.memAllocInt(patterns.indices().length).put(patterns.indices()).flip();
        try {
            elements.upload(indices, GL_STATIC_DRAW);
        } finally {
            MemoryUtil.memFree(indices);
        }
        staging = MemoryUtil.memAlloc(STRIDE * 256);
        instances.allocate(staging.capacity(), GL_STREAM_DRAW);
        for (int location = 1; location <= LAST_INSTANCE_LOCATION; location++) {
            glEnableVertexAttribArray(location);
            glVertexAttribDivisor(location, 1);
        }
        glBindVertexArray(0);
    }

    private void uploadGrid(int cells) {
        FloatBuffer vertices = MemoryUtil.memAllocFloat(2 * (cells + 1) * (cells + 1));
        try {
            for (int row = 0; row <= cells; row++) {
                for (int column = 0; column <= cells; column++) {
                    vertices.put(column).put(row);
                }
            }
            grid.upload(vertices.flip(), GL_STATIC_DRAW);
        } finally {
            MemoryUtil.memFree(vertices);
        }
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 2, GL_FLOAT, false, 0, 0);
    }

    /**
     * Draws patches {@code order[from]} .. {@code order[to - 1]} of the list with the bound terrain program, front to
     * back when the order is nearest first ({@link PatchOrder}): the instances of each pattern keep the order, and the
     * patterns are drawn in the order of their first patch.
     *
     * @param order       indices into {@code list}
     * @param copyOffsets x, z pairs, metres, indexed by {@link PatchList#copy(int)}
     */
    public void draw(PatchList list, int[] order, int from, int to, float[] copyOffsets, DrawStats stats) {
        int slots = (to - from) * PATTERNS_PER_PATCH;
        if (slots <= 0) {
            return;
        }
        // 1. the pattern of every (patch, part) slot, how many slots each pattern has, and its first slot
        if (slotPattern.length < slots) {
            slotPattern = new int[slots * 2];
        }
        java.util.Arrays.fill(runLength, 0);
        for (int k = 0; k < to - from; k++) {
            int i = order[from + k];
            int a = list.strideLog2(i);
            slotPattern[k * PATTERNS_PER_PATCH] = patterns.interior(a);
            for (Side side : SIDES) {
                slotPattern[k * PATTERNS_PER_PATCH + 1 + side.ordinal()] =
                        patterns.edge(side, a, list.sideStrideLog2(i, side));
            }
        }
        int used = 0;
        for (int s = 0; s < slots; s++) {
            if (runLength[slotPattern[s]]++ == 0) {
                drawOrder[used++] = slotPattern[s]; // patterns in the order of their nearest patch
            }
        }
        int start = 0;
        for (int p = 0; p < runStart.length; p++) {
            runStart[p] = start;
            start += runLength[p];
        }
        // 2. instance data sorted by pattern (a stable counting sort), streamed into a fresh buffer store
        if (staging.capacity() < slots * STRIDE) {
            staging = MemoryUtil.memRealloc(staging, slots * STRIDE * 2);
        }
        System.arraycopy(runStart, 0, cursor, 0, cursor.length);
        for (int s = 0; s < slots; s++) {
            writeInstance(list, order[from + s / PATTERNS_PER_PATCH], cursor[slotPattern[s]]++, copyOffsets);
        }
        staging.position(0).limit(slots * STRIDE);
        instances.allocate(slots * STRIDE, GL_STREAM_DRAW);
        instances.update(staging);
        staging.clear();
        // 3. one instanced draw per pattern in use
        vao.bind();
        instances.bind();
        for (int r = 0; r < used; r++) {
            int p = drawOrder[r];
            if (patterns.count(p) == 0) {
                continue;
            }
            long base = (long) runStart[p] * STRIDE;
            glVertexAttribIPointer(1, 4, GL_INT, STRIDE, base);
            glVertexAttribIPointer(2, 4, GL_INT, STRIDE, base + 16);
            glVertexAttribIPointer(3, 4, GL_INT, STRIDE, base + 32);
            glVertexAttribPointer(4, 2, GL_FLOAT, false, STRIDE, base + 48);
            glVertexAttribPointer(5, 1, GL_FLOAT, false, STRIDE, base + 56);
            glVertexAttribPointer(6, 4, GL_FLOAT, false, STRIDE, base + 60);
            glVertexAttribPointer(7, 4, GL_FLOAT, false, STRIDE, base + 76);
            glDrawElementsInstanced(GL_TRIANGLES, patterns.count(p), GL_UNSIGNED_INT,
                    (long) patterns.first(p) * Integer.BYTES, runLength[p]);
            stats.add(1, (long) patterns.count(p) / 3 * runLength[p]);
        }
        glBindVertexArray(0);
    }

    private void writeInstance(PatchList list, int i, int slot, float[] copyOffsets) {
        int at = slot * STRIDE;
        staging.putInt(at, list.originSampleX(i));
        staging.putInt(at + 4, list.originSampleZ(i));
        staging.putInt(at + 8, list.sampleStep(i));
        staging.putInt(at + 12, list.level(i));
        for (Side side : SIDES) {
            staging.putInt(at + 16 + 4 * side.ordinal(), list.sideLevel(i, side));
        }
        for (Corner corner : CORNERS) {
            staging.putInt(at + 32 + 4 * corner.ordinal(), list.cornerLevel(i, corner));
        }
        staging.putFloat(at + 48, copyOffsets[2 * list.copy(i)]);
        staging.putFloat(at + 52, copyOffsets[2 * list.copy(i) + 1]);
        staging.putFloat(at + 56, list.morph(i));
        for (Side side : SIDES) {
            staging.putFloat(at + 60 + 4 * side.ordinal(), list.sideMorph(i, side));
        }
        for (Corner corner : CORNERS) {
            staging.putFloat(at + 76 + 4 * corner.ordinal(), list.cornerMorph(i, corner));
        }
    }

    @Override
    public void close() {
        if (staging != null) {
            MemoryUtil.memFree(staging);
            staging = null;
        }
    }
}

package org.openworld.engine.environment;

import static org.lwjgl.opengl.GL15C.GL_DYNAMIC_DRAW;
import static org.lwjgl.opengl.GL31C.GL_UNIFORM_BUFFER;

import java.nio.ByteBuffer;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.gl.DepthTextureArray;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.GpuBuffer;
import org.openworld.engine.gl.Labelled;

/**
 * Where the sun cannot reach, for every lit shader: the shadow maps and the uniform block that says how to read them
 * ({@code shaders/common/shadow.glsl}, {@code sunVisibility}). The engine binds the map to
 * {@link org.openworld.engine.gl.SharedTexture#SHADOW_MAP} and the block to
 * {@link org.openworld.engine.gl.SharedBlock#SHADOW} before every pass but the one that draws the maps. Owned by the
 * system that casts the shadows; without one, the engine binds {@link #none}: everything is lit.
 *
 * @param map   one depth layer per cascade
 * @param block {@link #BLOCK_SIZE} bytes, laid out as {@code ShadowBlock} in {@code shaders/common/shadow.glsl}
 */
public record SunShadow(DepthTextureArray map, GpuBuffer block) implements Labelled {

    /** Bytes of the std140 block: 4 matrices and 5 vectors, each a mat4 or vec4, so no padding. */
    public static final int BLOCK_SIZE = 4 * 64 + 5 * 16;

    /** No shadow: an empty map and a block of zeros, whose cascade count 0 makes every point lit. */
    public static SunShadow none(GlContext gl) {
        GpuBuffer block = new GpuBuffer(gl, GL_UNIFORM_BUFFER);
        ByteBuffer zeros = MemoryUtil.memCalloc(BLOCK_SIZE);
        try {
            block.allocate(BLOCK_SIZE, GL_DYNAMIC_DRAW);
            block.update(zeros);
        } finally {
            MemoryUtil.memFree(zeros);
        }
        return new SunShadow(DepthTextureArray.empty(gl), block);
    }

    /** Names the map {@code name.map} and the block {@code name.block}. */
    @Override
    public void label(String name) {
        map.label(name + ".map");
        block.label(name + ".block");
    }

    @Override
    public void close() {
        map.close();
        block.close();
    }
}

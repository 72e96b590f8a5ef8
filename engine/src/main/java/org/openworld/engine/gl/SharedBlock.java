package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL15C.GL_DYNAMIC_DRAW;
import static org.lwjgl.opengl.GL31C.GL_UNIFORM_BUFFER;

import java.nio.ByteBuffer;
import org.lwjgl.system.MemoryUtil;

/**
 * Uniform blocks every shader may declare without its system binding them: each has a fixed binding point, and every
 * program that declares the block gets it bound there at link time. The engine keeps a buffer bound at each point
 * before every pass: the frame's, a shared resource's or the stand-in.
 */
public enum SharedBlock {
    /** {@code FrameBlock}: the pass's camera, the sun, time ({@code shaders/common/frame.glsl}, {@link FrameUniforms}). */
    FRAME("FrameBlock", 0, 0),
    /**
     * {@code ShadowBlock}: the sun's shadow cascades ({@code shaders/common/shadow.glsl}), std140: 4 matrices and 5
     * vectors, each a mat4 or vec4, so no padding. Its stand-in is zeros, whose cascade count 0 makes every point lit.
     */
    SHADOW("ShadowBlock", 1, 4 * 64 + 5 * 16),
    /**
     * {@code CloudShadowBlock}: where the cloud shadow map lies ({@code shaders/common/shadow.glsl}), std140: two
     * vec4s. Its stand-in is zeros, whose strength 0 lets all the sunlight through.
     */
    CLOUD_SHADOW("CloudShadowBlock", 2, 2 * 16),
    /**
     * {@code ForestCoverBlock}: where the forest cover map lies and the canopy's colours
     * ({@code shaders/common/forest.glsl}), std140: five vec4s. Its stand-in is zeros, whose strength 0 shows no forest.
     */
    FOREST_COVER("ForestCoverBlock", 3, 5 * 16);

    private final String block;
    private final int binding;
    private final int bytes;

    SharedBlock(String block, int binding, int bytes) {
        this.block = block;
        this.binding = binding;
        this.bytes = bytes;
    }

    /** The block's size in bytes; 0 for the frame's, written before every pass, which needs no stand-in. */
    public int bytes() {
        return bytes;
    }

    /** A buffer of zeros that stands in for this block where no shared resource binds it; null for the frame's. */
    public GpuBuffer standIn(GlContext gl) {
        if (bytes == 0) {
            return null;
        }
        GpuBuffer buffer = new GpuBuffer(gl, GL_UNIFORM_BUFFER);
        ByteBuffer zeros = MemoryUtil.memCalloc(bytes);
        try {
            buffer.allocate(bytes, GL_DYNAMIC_DRAW);
            buffer.update(zeros);
        } finally {
            MemoryUtil.memFree(zeros);
        }
        return buffer;
    }

    /** The block's name in GLSL. */
    public String block() {
        return block;
    }

    /** The uniform buffer binding point. */
    public int binding() {
        return binding;
    }
}

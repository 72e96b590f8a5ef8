package org.openworld.engine.environment;

import static org.lwjgl.opengl.GL15C.GL_DYNAMIC_DRAW;
import static org.lwjgl.opengl.GL31C.GL_UNIFORM_BUFFER;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.GpuBuffer;
import org.openworld.engine.gl.Labelled;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.Texture2D;

/**
 * The sunlight the clouds let through, for every lit shader: a map of the transmittance of the sun's ray through the
 * cloud volume over one tile of the cloud field, and the block that says where it lies
 * ({@code shaders/common/shadow.glsl}, {@code cloudShadow}, folded into {@code sunVisibility}, so the ground, the
 * water, the trees and the snow are all shadowed by the one lookup). The engine binds the map to
 * {@link org.openworld.engine.gl.SharedTexture#CLOUD_SHADOW_MAP} and the block to
 * {@link org.openworld.engine.gl.SharedBlock#CLOUD_SHADOW} before every pass. Owned by the volumetric clouds; without
 * them the engine binds {@link #none}: a block of zeros, whose strength 0 lets all the sunlight through.
 *
 * @param map   the transmittance (R16F), one texel per field sample, wrapping as the field does
 * @param block {@link #BLOCK_SIZE} bytes, laid out as {@code CloudShadowBlock} in {@code shaders/common/shadow.glsl}
 */
public record CloudShadow(Texture2D map, GpuBuffer block) implements Labelled {

    /** Bytes of the std140 block: two vec4s. */
    public static final int BLOCK_SIZE = 2 * 16;

    /** No clouds: a 1 × 1 map that lets everything through, and a block of zeros. */
    public static CloudShadow none(GlContext gl) {
        GpuBuffer block = emptyBlock(gl);
        FloatBuffer clear = MemoryUtil.memAllocFloat(1).put(1).flip();
        try {
            Texture2D map = Texture2D.empty(gl, 1, 1, Format.R16F, Sampling.NEAREST_CLAMP);
            map.upload(0, 0, 1, clear);
            return new CloudShadow(map, block);
        } finally {
            MemoryUtil.memFree(clear);
        }
    }

    /** A block of {@link #BLOCK_SIZE} zeros: strength 0 until {@link #write} says otherwise. */
    public static GpuBuffer emptyBlock(GlContext gl) {
        GpuBuffer block = new GpuBuffer(gl, GL_UNIFORM_BUFFER);
        ByteBuffer zeros = MemoryUtil.memCalloc(BLOCK_SIZE);
        try {
            block.allocate(BLOCK_SIZE, GL_DYNAMIC_DRAW);
            block.update(zeros);
            return block;
        } finally {
            MemoryUtil.memFree(zeros);
        }
    }

    /**
     * Writes the block: the base of the clouds (m above sea level), the field's tile (m), the wind's offset of the
     * field (m, world x and z) and the strength (1: the map darkens, 0: it is ignored).
     */
    public void write(float baseM, float tileM, float windX, float windZ, float strength) {
        ByteBuffer data = MemoryUtil.memAlloc(BLOCK_SIZE);
        try {
            data.asFloatBuffer().put(new float[] {baseM, 1 / tileM, windX, windZ, strength, 0, 0, 0});
            block.update(data);
        } finally {
            MemoryUtil.memFree(data);
        }
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

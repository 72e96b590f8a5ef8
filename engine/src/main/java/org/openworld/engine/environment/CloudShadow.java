package org.openworld.engine.environment;

import java.nio.ByteBuffer;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.core.SharedResource;
import org.openworld.engine.gl.GpuBuffer;
import org.openworld.engine.gl.SharedBlock;
import org.openworld.engine.gl.SharedTexture;
import org.openworld.engine.gl.Texture2D;

/**
 * The sunlight the clouds let through, for every lit shader: a map of the transmittance of the sun's ray through the
 * cloud volume over one tile of the cloud field, and the block that says where it lies
 * ({@code shaders/common/shadow.glsl}, {@code cloudShadow}, folded into {@code sunVisibility}, so the ground, the
 * water, the trees and the snow are all shadowed by the one lookup). The engine binds the map to
 * {@link org.openworld.engine.gl.SharedTexture#CLOUD_SHADOW_MAP} and the block to
 * {@link org.openworld.engine.gl.SharedBlock#CLOUD_SHADOW} before every pass. Owned by the volumetric clouds; without
 * them the engine binds the stand-ins ({@link SharedTexture#standIn}): a block of zeros, whose strength 0 lets all
 * the sunlight through.
 *
 * @param map   the transmittance (RG16F) along the sun's ray (r) and straight up (g, where the snow falls:
 *              {@code snowfallShare}), one texel per field sample, wrapping as the field does
 * @param block {@link #BLOCK_SIZE} bytes, laid out as {@code CloudShadowBlock} in {@code shaders/common/shadow.glsl}
 */
public record CloudShadow(Texture2D map, GpuBuffer block) implements MapAndBlock, SharedResource {

    /** Bytes of the std140 block: two vec4s ({@link SharedBlock#CLOUD_SHADOW}). */
    public static final int BLOCK_SIZE = SharedBlock.CLOUD_SHADOW.bytes();

    /** Binds the map to {@link SharedTexture#CLOUD_SHADOW_MAP} and the block to {@link SharedBlock#CLOUD_SHADOW}. */
    @Override
    public void bindShared() {
        map.bind(SharedTexture.CLOUD_SHADOW_MAP.unit());
        block.bindBase(SharedBlock.CLOUD_SHADOW.binding());
    }

    /**
     * Writes the block: the base of the clouds (m above sea level), the field's tile (m), the wind's offset of the
     * field (m, world x and z, from the world's origin: the shader adds the render origin of its own pass, so the
     * shadow stays put on a frame the origin steps after the block was written) and the strength (1: the map
     * darkens, 0: it is ignored).
     */
    public void write(float baseM, float tileM, float windX, float windZ, float strength) {
        ByteBuffer data = MemoryUtil.memAlloc(BLOCK_SIZE);
        try {
            data.asFloatBuffer().put(new float[] {baseM, 1 / tileM, windX, windZ, strength, tileM, 0, 0});
            block.update(data);
        } finally {
            MemoryUtil.memFree(data);
        }
    }
}

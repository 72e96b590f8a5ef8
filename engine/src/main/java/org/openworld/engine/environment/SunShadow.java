package org.openworld.engine.environment;

import org.openworld.engine.core.SharedResource;
import org.openworld.engine.gl.DepthTextureArray;
import org.openworld.engine.gl.GpuBuffer;
import org.openworld.engine.gl.SharedBlock;
import org.openworld.engine.gl.SharedTexture;

/**
 * Where the sun cannot reach, for every lit shader: the shadow maps and the uniform block that says how to read them
 * ({@code shaders/common/shadow.glsl}, {@code sunVisibility}), shared with every pass after the one that draws the
 * maps ({@link SharedResource}). Owned by the system that casts the shadows; without one, the engine binds the
 * stand-ins of {@link SharedTexture#SHADOW_MAP} and {@link SharedBlock#SHADOW}: everything is lit.
 *
 * @param map   one depth layer per cascade
 * @param block {@link #BLOCK_SIZE} bytes, laid out as {@code ShadowBlock} in {@code shaders/common/shadow.glsl}
 */
public record SunShadow(DepthTextureArray map, GpuBuffer block) implements MapAndBlock, SharedResource {

    /** Bytes of the std140 block ({@link SharedBlock#SHADOW}). */
    public static final int BLOCK_SIZE = SharedBlock.SHADOW.bytes();

    /** Binds the maps to {@link SharedTexture#SHADOW_MAP} and the block to {@link SharedBlock#SHADOW}. */
    @Override
    public void bindShared() {
        map.bind(SharedTexture.SHADOW_MAP.unit());
        block.bindBase(SharedBlock.SHADOW.binding());
    }
}

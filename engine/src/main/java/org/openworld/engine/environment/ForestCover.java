package org.openworld.engine.environment;

import java.nio.ByteBuffer;
import java.util.function.BooleanSupplier;
import org.joml.Vector3fc;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.core.SharedResource;
import org.openworld.engine.gl.GpuBuffer;
import org.openworld.engine.gl.SharedBlock;
import org.openworld.engine.gl.SharedTexture;
import org.openworld.engine.gl.Texture2D;

/**
 * The forests beyond the plants' reach, for the far ground's material: a map of how much of the ground the canopy
 * hides and of which kinds it is, over a window around the viewer that wraps ({@code GL_REPEAT}, so the window moves
 * by rewriting the map, never by moving a texture coordinate), and a block with the window's period, the distances
 * over which the cover fades in where the plants fade out, and the kinds' canopy colours
 * ({@code shaders/common/forest.glsl}, {@code forestCover}). The engine binds the map to
 * {@link SharedTexture#FOREST_COVER} and the block to {@link SharedBlock#FOREST_COVER} before every pass. Owned by the
 * vegetation; without it the stand-ins show no forest.
 *
 * @param map   RGBA8: rgb each kind's share of the canopy seen from above, a the share of the ground it hides; one
 *              texel per {@code extent / size} metres, texel (i, j) at world (x, z) ≡ ((i + ½), (j + ½)) · that,
 *              modulo the extent
 * @param block {@link SharedBlock#FOREST_COVER}'s bytes, laid out as {@code ForestCoverBlock}
 * @param shown whether the forests are drawn now (their system switched on)
 */
public record ForestCover(Texture2D map, GpuBuffer block, BooleanSupplier shown) implements MapAndBlock,
        SharedResource {

    /**
     * Binds the map to {@link SharedTexture#FOREST_COVER} and the block to {@link SharedBlock#FOREST_COVER} while the
     * forests are {@code shown} (their system is on); otherwise leaves the stand-ins bound.
     */
    @Override
    public void bindShared() {
        if (shown.getAsBoolean()) {
            map.bind(SharedTexture.FOREST_COVER.unit());
            block.bindBase(SharedBlock.FOREST_COVER.binding());
        }
    }

    /**
     * Writes the block.
     *
     * @param extent  metres: the map's period, a power of two, as the render origin's step is (so the origin's share
     *                of a world position modulo the extent is exact in the shader)
     * @param reach   metres from the viewer to which the map holds the present ground (it fades out over the last
     *                fifth)
     * @param fade    metres from the viewer where the cover starts to show and where it is full: where the plants
     *                shrink away
     * @param colours each kind's canopy albedo, linear RGB, in the order of the map's channels
     * @param sideOverTop each kind's outline seen from the side over its outline seen from above, in that order
     */
    public void write(double extent, double reach, float[] fade, Vector3fc[] colours, float[] sideOverTop) {
        ByteBuffer data = MemoryUtil.memCalloc(SharedBlock.FOREST_COVER.bytes());
        try {
            data.asFloatBuffer().put(new float[] {(float) (1 / extent), (float) extent, (float) reach, 1,
                fade[0], fade[1], 0, 0});
            for (int k = 0; k < colours.length; k++) {
                colours[k].get(32 + 16 * k, data);
                data.putFloat(32 + 16 * k + 12, sideOverTop[k]);
            }
            block.update(data);
        } finally {
            MemoryUtil.memFree(data);
        }
    }
}

package org.openworld.engine.gl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL30C.*;

import java.nio.FloatBuffer;
import java.util.Collections;
import java.util.List;
import java.util.stream.IntStream;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.GlTest;
import org.openworld.engine.HeadlessGl;

/**
 * The engine's texture memory count against what the real driver says it holds: each texture's levels, sizes and
 * layers read back with {@code glGetTexLevelParameteri}, its texel size from the channels' bits. The count grows by
 * exactly that when a texture is made and shrinks by it when closed; the peak stays.
 */
@GlTest
class TextureMemoryGlTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    private static final int[] CUBE_FACES = IntStream.range(0, 6).map(f -> GL_TEXTURE_CUBE_MAP_POSITIVE_X + f).toArray();

    @Test
    void aMipmappedTextureAndAnArrayAddWhatTheDriverHoldsAndGiveItBack() {
        TextureMemory memory = GL.context().textureMemory();
        long before = memory.bytes();
        Texture2D heights = Texture2D.withMips(GL.context(), 64, 16, Format.R32F, Sampling.TRILINEAR_CLAMP);
        long heightsBytes = driverBytes(heights, GL_TEXTURE_2D);
        assertEquals(before + heightsBytes, memory.bytes(), "a 64 × 16 R32F texture with its 7 levels");
        assertTrue(heightsBytes > 64 * 16 * 4, "the levels below 0 count too: " + heightsBytes + " B");

        byte[] layer = new byte[4 * 8 * 4];
        TextureArray materials = TextureArray.repeatingMipmapped(GL.context(), 8, 4, Format.RGBA8,
                Collections.nCopies(3, layer));
        long materialsBytes = driverBytes(materials, GL_TEXTURE_2D_ARRAY);
        assertEquals(before + heightsBytes + materialsBytes, memory.bytes(), "three 8 × 4 RGBA8 layers, mipmapped");
        assertTrue(materialsBytes > 3 * 8 * 4 * 4, "the mipmaps made by glGenerateMipmap count: " + materialsBytes);

        heights.close();
        assertEquals(before + materialsBytes, memory.bytes());
        materials.close();
        materials.close(); // closing twice gives back once
        assertEquals(before, memory.bytes());
        assertEquals(before + heightsBytes + materialsBytes, memory.peakBytes(), "the peak stays");
    }

    @Test
    void everyKindOfTextureCountsWhatTheDriverHolds() {
        TextureMemory memory = GL.context().textureMemory();
        long before = memory.bytes();
        FloatBuffer volume = MemoryUtil.memCallocFloat(4 * 4 * 2);
        try (CubeMapTexture target = CubeMapTexture.renderTarget(GL.context(), 8);
             CubeMapTexture sky = CubeMapTexture.fromDirections(GL.context(), 4, d -> new Vector3f(d).absolute());
             DepthTextureArray shadows = DepthTextureArray.of(GL.context(), 16, 3, Format.DEPTH24);
             Texture3D clouds = Texture3D.of(GL.context(), 4, 4, 2, Format.R16F, Sampling.LINEAR_REPEAT, volume);
             Framebuffer scene = Framebuffer.scene(GL.context(), 8, 6)) {
            long expected = driverBytes(target, CUBE_FACES) + driverBytes(sky, CUBE_FACES)
                    + driverBytes(shadows, GL_TEXTURE_2D_ARRAY) + driverBytes(clouds, GL_TEXTURE_3D)
                    + driverBytes(scene.color(), GL_TEXTURE_2D) + driverBytes(scene.depth(), GL_TEXTURE_2D);
            assertEquals(before + expected, memory.bytes());
        } finally {
            MemoryUtil.memFree(volume);
        }
        assertEquals(before, memory.bytes());
    }

    @Test
    void eachFormatsTexelSizeIsItsChannelsBitsAndDepth24TakesAWord() {
        for (Format format : Format.values()) {
            try (Texture2D t = Texture2D.empty(GL.context(), 1, 1, format, Sampling.NEAREST_CLAMP)) {
                int bits = channelBits(GL_TEXTURE_2D);
                assertEquals(0, bits % 8, format + ": " + bits + " bits");
                int expected = format == Format.DEPTH24 ? 4 : bits / 8;
                assertTrue(format != Format.DEPTH24 || bits >= 24, "depth24 has " + bits + " bits");
                assertEquals(expected, format.bytesPerTexel(), format + ": " + bits + " bits");
            }
        }
    }

    /**
     * The bytes the driver says a texture holds: over each image target (one, or a cube map's six faces) and each
     * level the driver has made, width × height × depth (layers or slices) × the channels' bytes, a 24-bit depth in 4.
     */
    private static long driverBytes(GlTexture texture, int... images) {
        texture.bind(0);
        long bytes = 0;
        for (int image : images) {
            int bits = channelBits(image);
            long texelBytes = texture.format().isDepth() && bits == 24 ? 4 : bits / 8;
            for (int level = 0; glGetTexLevelParameteri(image, level, GL_TEXTURE_WIDTH) > 0; level++) {
                bytes += (long) glGetTexLevelParameteri(image, level, GL_TEXTURE_WIDTH)
                        * glGetTexLevelParameteri(image, level, GL_TEXTURE_HEIGHT)
                        * glGetTexLevelParameteri(image, level, GL_TEXTURE_DEPTH) * texelBytes;
            }
        }
        return bytes;
    }

    /** The bits of one texel of level 0, over every channel the driver reports. */
    private static int channelBits(int image) {
        return List.of(GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE, GL_TEXTURE_ALPHA_SIZE,
                        GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_STENCIL_SIZE).stream()
                .mapToInt(channel -> glGetTexLevelParameteri(image, 0, channel)).sum();
    }
}

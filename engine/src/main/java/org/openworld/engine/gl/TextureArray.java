package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL30C.*;

import java.nio.Buffer;
import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.util.List;
import java.util.Locale;
import org.lwjgl.opengl.GL;
import org.lwjgl.opengl.GLCapabilities;
import org.lwjgl.system.MemoryUtil;

/**
 * A 2D texture array ({@code GL_TEXTURE_2D_ARRAY}): equal-sized layers sampled in GLSL as
 * {@code texture(sampler2DArray, vec3(uv, layer))}, so one texture unit holds a whole family of images, e.g. the
 * terrain materials. Made with {@link #repeatingMipmapped}: uploaded once, mipmapped by {@code glGenerateMipmap},
 * sampled {@link Sampling#TRILINEAR_REPEAT}; or {@link #empty} and filled piece by piece.
 */
public final class TextureArray extends GlTexture {

    /**
     * Anisotropic filtering asked for where the driver has it (core in 4.6, an extension before) and a GPU runs it:
     * ground seen at grazing angles otherwise blurs to its mean within a few metres. 8 samples is where the gain
     * levels off.
     */
    private static final float MAX_ANISOTROPY = 8;
    private static final int GL_TEXTURE_MAX_ANISOTROPY = 0x84FE;
    private static final int GL_MAX_TEXTURE_MAX_ANISOTROPY = 0x84FF;

    private TextureArray(GlContext gl, int width, int height, int layers, Format format, Sampling sampling) {
        super(gl, GL_TEXTURE_2D_ARRAY, width, height, layers, format, sampling);
    }

    /**
     * Storage for equal layers without data or mips, filled a rectangle at a time with {@link #upload}: e.g. the
     * levels of a clipmap, streamed piece by piece.
     */
    public static TextureArray empty(GlContext gl, int width, int height, int layers, Format format,
                                     Sampling sampling) {
        TextureArray t = new TextureArray(gl, width, height, layers, format, sampling);
        glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, format.internalFormat(), width, height, layers, 0, format.format(),
                format.type(), (ByteBuffer) null);
        t.setLevels(1);
        t.stored(1);
        return t;
    }

    /**
     * Writes a rectangle of one layer; {@code data} holds its rows in this texture's {@link Format#format()} and
     * {@link Format#type()} (floats or bytes).
     */
    public void upload(int layer, int x, int y, int width, int height, Buffer data) {
        bindForUpdate();
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        Format f = format();
        if (data instanceof FloatBuffer floats) {
            glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, x, y, layer, width, height, 1, f.format(), f.type(), floats);
        } else if (data instanceof ByteBuffer bytes) {
            glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, x, y, layer, width, height, 1, f.format(), f.type(), bytes);
        } else {
            throw new IllegalArgumentException("upload takes a FloatBuffer or a ByteBuffer, got " + data.getClass());
        }
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    }

    /**
     * Uploads equal-sized layers of 4-byte texels (rows from v = 0) and builds the full mipmap chain; sampled
     * trilinearly (and anisotropically where available), repeating in u and v, for tiling textures.
     *
     * @param format {@link Format#SRGB8_ALPHA8} for colour, {@link Format#RGBA8} for data
     * @param texels one array of {@code 4 width height} bytes per layer
     */
    public static TextureArray repeatingMipmapped(GlContext gl, int width, int height, Format format,
                                                  List<byte[]> texels) {
        if (texels.isEmpty()) {
            throw new IllegalArgumentException("texture array needs a layer, got none");
        }
        TextureArray t = new TextureArray(gl, width, height, texels.size(), format, Sampling.TRILINEAR_REPEAT);
        int layerBytes = 4 * width * height;
        ByteBuffer all = MemoryUtil.memAlloc(layerBytes * texels.size());
        try {
            for (byte[] layer : texels) {
                if (layer.length != layerBytes) {
                    throw new IllegalArgumentException("layer of " + layer.length + " bytes, expected " + layerBytes);
                }
                all.put(layer);
            }
            all.flip();
            glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
            glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, format.internalFormat(), width, height, texels.size(), 0,
                    format.format(), format.type(), all);
        } catch (RuntimeException e) {
            t.close();
            throw e;
        } finally {
            MemoryUtil.memFree(all);
        }
        glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
        t.stored(fullChain(width, height));
        GLCapabilities caps = GL.getCapabilities();
        boolean hasAnisotropy = caps.OpenGL46 || caps.GL_ARB_texture_filter_anisotropic
                || caps.GL_EXT_texture_filter_anisotropic;
        if (hasAnisotropy && !isSoftwareRenderer(gl)) {
            float max = glGetFloat(GL_MAX_TEXTURE_MAX_ANISOTROPY);
            glTexParameterf(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_ANISOTROPY, Math.min(MAX_ANISOTROPY, max));
        }
        return t;
    }

    /**
     * Mesa's CPU rasterisers: their anisotropic filtering is exact and slow, measured at minutes for one 640 × 360
     * frame of terrain seen at grazing angles on llvmpipe (against 0.2 s with trilinear filtering), so they keep
     * trilinear filtering; on a GPU anisotropy costs next to nothing.
     */
    private static boolean isSoftwareRenderer(GlContext gl) {
        String renderer = gl.renderer().toLowerCase(Locale.ROOT);
        return renderer.contains("llvmpipe") || renderer.contains("softpipe") || renderer.contains("swrast");
    }

    public int layers() {
        return depth();
    }
}

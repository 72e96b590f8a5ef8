package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL30C.*;

import java.nio.ByteBuffer;
import java.util.List;
import org.lwjgl.opengl.GL;
import org.lwjgl.opengl.GLCapabilities;
import org.lwjgl.system.MemoryUtil;

/**
 * A 2D texture array ({@code GL_TEXTURE_2D_ARRAY}): equal-sized layers sampled in GLSL as
 * {@code texture(sampler2DArray, vec3(uv, layer))}, so one texture unit holds a whole family of images, e.g. the
 * terrain materials. Made with {@link #repeatingMipmapped}: uploaded once, mipmapped by {@code glGenerateMipmap}.
 */
public final class TextureArray extends GlTexture {

    /** sRGB-encoded colour with linear alpha: sampling decodes to linear light, mipmaps average in linear light. */
    public static final Texture2D.Format SRGB8_ALPHA8 = new Texture2D.Format(GL_SRGB8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE);

    /**
     * Anisotropic filtering asked for where the driver has it (core in 4.6, an extension before) and a GPU runs it:
     * ground seen at grazing angles otherwise blurs to its mean within a few metres. 8 samples is where the gain
     * levels off.
     */
    private static final float MAX_ANISOTROPY = 8;
    private static final int GL_TEXTURE_MAX_ANISOTROPY = 0x84FE;
    private static final int GL_MAX_TEXTURE_MAX_ANISOTROPY = 0x84FF;

    private final int width;
    private final int height;
    private final int layers;

    private TextureArray(GlContext gl, int width, int height, int layers) {
        super(gl, GL_TEXTURE_2D_ARRAY);
        this.width = width;
        this.height = height;
        this.layers = layers;
    }

    /**
     * Uploads equal-sized layers of 4-byte texels (rows from v = 0) and builds the full mipmap chain; sampled
     * trilinearly (and anisotropically where available), repeating in u and v, for tiling textures.
     *
     * @param format e.g. {@link #SRGB8_ALPHA8} for colour, {@link Texture2D.Format#RGBA8} for data
     * @param texels one array of {@code 4 width height} bytes per layer
     */
    public static TextureArray repeatingMipmapped(GlContext gl, int width, int height, Texture2D.Format format,
                                                  List<byte[]> texels) {
        if (width <= 0 || height <= 0 || texels.isEmpty()) {
            throw new IllegalArgumentException("texture array needs a positive size and a layer, got " + width + "x"
                    + height + "x" + texels.size());
        }
        int layerBytes = 4 * width * height;
        TextureArray t = new TextureArray(gl, width, height, texels.size());
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
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_REPEAT);
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
        String renderer = gl.renderer().toLowerCase(java.util.Locale.ROOT);
        return renderer.contains("llvmpipe") || renderer.contains("softpipe") || renderer.contains("swrast");
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    public int layers() {
        return layers;
    }
}

package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL30C.*;

import java.nio.Buffer;
import java.nio.ByteBuffer;
import java.nio.FloatBuffer;

/**
 * A 2D texture with its size and format: created empty (a render target, or storage filled level by level with
 * {@link #upload}), optionally with a mip chain.
 */
public final class Texture2D extends GlTexture {

    /** Sampling and wrap, chosen per use. */
    public record Sampling(int minFilter, int magFilter, int wrap) {
        public static final Sampling NEAREST_CLAMP = new Sampling(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE);
        /** Bilinear, clamped at the edges: a look-up table read between its texels. */
        public static final Sampling LINEAR_CLAMP = new Sampling(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
        /** Exact texels by {@code texelFetch} from every mip level (a height pyramid). */
        public static final Sampling NEAREST_MIPMAP = new Sampling(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, GL_REPEAT);
        /** Trilinear and tiling: a map that wraps around (a periodic world). */
        public static final Sampling TRILINEAR_REPEAT = new Sampling(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT);
        /** Trilinear and clamped at the edges (an imported, non-periodic map). */
        public static final Sampling TRILINEAR_CLAMP = new Sampling(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    }

    /** The three numbers GL needs for a pixel format, e.g. RGBA8 = (GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE). */
    public record Format(int internalFormat, int format, int type) {
        public static final Format RGBA8 = new Format(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE);
        public static final Format DEPTH24_STENCIL8 = new Format(GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8);
        public static final Format DEPTH32F = new Format(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT);
        /** One float per texel, e.g. heights in metres. */
        public static final Format R32F = new Format(GL_R32F, GL_RED, GL_FLOAT);
        /** Two half floats per texel, uploaded from floats, e.g. a height gradient. */
        public static final Format RG16F = new Format(GL_RG16F, GL_RG, GL_FLOAT);
        /** Three half floats per texel, uploaded from floats, e.g. radiance that may exceed 1. */
        public static final Format RGB16F = new Format(GL_RGB16F, GL_RGB, GL_FLOAT);
        /** One half float per texel, uploaded from floats, e.g. a cloud density field. */
        public static final Format R16F = new Format(GL_R16F, GL_RED, GL_FLOAT);
        /** Four half floats per texel, uploaded from floats, e.g. a table of linear colours above 1. */
        public static final Format RGBA16F = new Format(GL_RGBA16F, GL_RGBA, GL_FLOAT);
        /** One byte per texel, e.g. a coverage mask. */
        public static final Format R8 = new Format(GL_R8, GL_RED, GL_UNSIGNED_BYTE);
    }

    private final int width;
    private final int height;
    private final Format format;

    private Texture2D(GlContext gl, int width, int height, Format format, Sampling sampling) {
        super(gl, GL_TEXTURE_2D);
        this.width = width;
        this.height = height;
        this.format = format;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, sampling.minFilter());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, sampling.magFilter());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, sampling.wrap());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, sampling.wrap());
    }

    /** Storage without data, e.g. a render target. */
    public static Texture2D empty(GlContext gl, int width, int height, Format format, Sampling sampling) {
        requirePositive(width, height);
        Texture2D t = new Texture2D(gl, width, height, format, sampling);
        glTexImage2D(GL_TEXTURE_2D, 0, format.internalFormat(), width, height, 0, format.format(), format.type(),
                (ByteBuffer) null);
        return t;
    }

    /**
     * Storage for a full mip chain without data (levels 0 .. log2(max(width, height))), to be filled with
     * {@link #upload} level by level, or level 0 then {@link #generateMipmaps()}.
     */
    public static Texture2D withMips(GlContext gl, int width, int height, Format format, Sampling sampling) {
        requirePositive(width, height);
        Texture2D t = new Texture2D(gl, width, height, format, sampling);
        int levels = 32 - Integer.numberOfLeadingZeros(Math.max(width, height));
        for (int level = 0; level < levels; level++) {
            glTexImage2D(GL_TEXTURE_2D, level, format.internalFormat(), Math.max(1, width >> level),
                    Math.max(1, height >> level), 0, format.format(), format.type(), (ByteBuffer) null);
        }
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels - 1);
        return t;
    }

    private static void requirePositive(int width, int height) {
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("texture size must be positive, got " + width + "x" + height);
        }
    }

    /**
     * Writes rows {@code y .. y + rows - 1} of one mip level; {@code data} holds {@code rows} full rows in this
     * texture's {@link Format#format()} and {@link Format#type()} (floats or bytes). Large maps upload in strips, so
     * the staging buffer stays small.
     */
    public void upload(int level, int y, int rows, Buffer data) {
        bindForUpdate();
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        int levelWidth = Math.max(1, width >> level);
        if (data instanceof FloatBuffer floats) {
            glTexSubImage2D(GL_TEXTURE_2D, level, 0, y, levelWidth, rows, format.format(), format.type(), floats);
        } else if (data instanceof ByteBuffer bytes) {
            glTexSubImage2D(GL_TEXTURE_2D, level, 0, y, levelWidth, rows, format.format(), format.type(), bytes);
        } else {
            throw new IllegalArgumentException("upload takes a FloatBuffer or a ByteBuffer, got " + data.getClass());
        }
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    }

    /** Fills levels 1.. from level 0 by averaging (the GL's box filter). */
    public void generateMipmaps() {
        bindForUpdate();
        glGenerateMipmap(GL_TEXTURE_2D);
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    public Format format() {
        return format;
    }
}

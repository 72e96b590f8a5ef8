package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL30C.*;

import java.nio.FloatBuffer;

/**
 * A 3D texture ({@code GL_TEXTURE_3D}, {@code sampler3D} in GLSL) with its size and format, filled from floats: a
 * volume sampled with trilinear filtering, such as the clouds' density over two axes of space and one of time, or a
 * table over three parameters. No mip chain: both uses are sampled at about one texel per pixel or coarser per axis.
 */
public final class Texture3D extends GlTexture {

    /** Filtering and wrap, the same on all three axes (s, t, r). */
    public record Sampling3D(int minFilter, int magFilter, int wrap) {
        /** Trilinear between the eight nearest texels, wrapping: a field periodic along every axis. */
        public static final Sampling3D LINEAR_REPEAT = new Sampling3D(GL_LINEAR, GL_LINEAR, GL_REPEAT);
        /** Trilinear, clamped to the edge texels: a table whose axes end at the first and last entry. */
        public static final Sampling3D LINEAR_CLAMP = new Sampling3D(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    }

    private final int width;
    private final int height;
    private final int depth;
    private final Texture2D.Format format;

    private Texture3D(GlContext gl, int width, int height, int depth, Texture2D.Format format, Sampling3D sampling) {
        super(gl, GL_TEXTURE_3D);
        this.width = width;
        this.height = height;
        this.depth = depth;
        this.format = format;
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, sampling.minFilter());
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, sampling.magFilter());
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, sampling.wrap());
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_T, sampling.wrap());
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, sampling.wrap());
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAX_LEVEL, 0); // no mip chain: complete with level 0 alone
    }

    /**
     * A volume of {@code width × height × depth} texels.
     *
     * @param format a float format ({@code R16F}, {@code R32F}, {@code RGBA16F}, ...): the data are floats
     * @param data   the texels, x fastest, then y, then z, {@link #components} floats each; null for storage only,
     *               to be filled by {@link #upload}
     */
    public static Texture3D of(GlContext gl, int width, int height, int depth, Texture2D.Format format,
                               Sampling3D sampling, FloatBuffer data) {
        if (width <= 0 || height <= 0 || depth <= 0) {
            throw new IllegalArgumentException("texture size must be positive, got " + width + "x" + height + "x"
                    + depth);
        }
        if (format.type() != GL_FLOAT) {
            throw new IllegalArgumentException("a 3D texture is filled from floats; its format must take GL_FLOAT");
        }
        if (data != null) {
            checkSize(width, height, depth, format, data);
        }
        Texture3D t = new Texture3D(gl, width, height, depth, format, sampling);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexImage3D(GL_TEXTURE_3D, 0, format.internalFormat(), width, height, depth, 0, format.format(),
                format.type(), data);
        return t;
    }

    /** Replaces every texel; {@code data} as in {@link #of}. */
    public void upload(FloatBuffer data) {
        checkSize(width, height, depth, format, data);
        bindForUpdate();
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, width, height, depth, format.format(), format.type(), data);
    }

    private static void checkSize(int width, int height, int depth, Texture2D.Format format, FloatBuffer data) {
        long expected = (long) width * height * depth * components(format);
        if (data.remaining() != expected) {
            throw new IllegalArgumentException("a " + width + "x" + height + "x" + depth + " volume takes " + expected
                    + " floats, got " + data.remaining());
        }
    }

    /** Floats per texel for a pixel format's {@link Texture2D.Format#format()}: 1 red, 2 RG, 3 RGB, 4 RGBA. */
    static int components(Texture2D.Format format) {
        return switch (format.format()) {
            case GL_RED -> 1;
            case GL_RG -> 2;
            case GL_RGB -> 3;
            case GL_RGBA -> 4;
            default -> throw new IllegalArgumentException("no colour format: 0x" + Integer.toHexString(format.format()));
        };
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    public int depth() {
        return depth;
    }

    public Texture2D.Format format() {
        return format;
    }
}

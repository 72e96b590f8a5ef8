package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL30C.*;

import java.nio.FloatBuffer;

/**
 * A 3D texture ({@code GL_TEXTURE_3D}, {@code sampler3D} in GLSL), filled from floats: a volume sampled with
 * trilinear filtering ({@link Sampling#LINEAR_REPEAT}, {@link Sampling#LINEAR_CLAMP}), such as the clouds' density
 * over two axes of space and one of time, or a table over three parameters. No mip chain: both uses are sampled at
 * about one texel per pixel or coarser per axis.
 */
public final class Texture3D extends GlTexture {

    private Texture3D(GlContext gl, int width, int height, int depth, Format format, Sampling sampling) {
        super(gl, GL_TEXTURE_3D, width, height, depth, format, sampling);
        setLevels(1);
    }

    /**
     * A volume of {@code width × height × depth} texels.
     *
     * @param format a float format ({@code R16F}, {@code R32F}, {@code RGBA16F}, ...): the data are floats
     * @param data   the texels, x fastest, then y, then z, {@link Format#components()} floats each; null for storage
     *               only, to be filled by {@link #upload}
     */
    public static Texture3D of(GlContext gl, int width, int height, int depth, Format format, Sampling sampling,
                               FloatBuffer data) {
        if (format.type() != GL_FLOAT || format.isDepth()) {
            throw new IllegalArgumentException("a 3D texture is filled from floats; its format must take GL_FLOAT");
        }
        if (data != null && width > 0 && height > 0 && depth > 0) {
            checkSize(width, height, depth, format, data);
        }
        Texture3D t = new Texture3D(gl, width, height, depth, format, sampling);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexImage3D(GL_TEXTURE_3D, 0, format.internalFormat(), width, height, depth, 0, format.format(),
                format.type(), data);
        t.stored(1);
        return t;
    }

    /** Replaces every texel; {@code data} as in {@link #of}. */
    public void upload(FloatBuffer data) {
        checkSize(width(), height(), depth(), format(), data);
        bindForUpdate();
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, width(), height(), depth(), format().format(), format().type(),
                data);
    }

    private static void checkSize(int width, int height, int depth, Format format, FloatBuffer data) {
        long expected = (long) width * height * depth * format.components();
        if (data.remaining() != expected) {
            throw new IllegalArgumentException("a " + width + "x" + height + "x" + depth + " volume takes " + expected
                    + " floats, got " + data.remaining());
        }
    }
}

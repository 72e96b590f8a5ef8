package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL30C.*;

import java.nio.Buffer;
import java.nio.ByteBuffer;
import java.nio.FloatBuffer;

/**
 * A 2D texture: created empty (a render target, or storage filled level by level with {@link #upload}), optionally
 * with a mip chain. Size, {@link Format} and {@link Sampling} as every texture ({@link GlTexture}).
 */
public final class Texture2D extends GlTexture {

    private Texture2D(GlContext gl, int width, int height, Format format, Sampling sampling) {
        super(gl, GL_TEXTURE_2D, width, height, 1, format, sampling);
    }

    /** Storage without data, e.g. a render target. */
    public static Texture2D empty(GlContext gl, int width, int height, Format format, Sampling sampling) {
        Texture2D t = new Texture2D(gl, width, height, format, sampling);
        t.allocate(1);
        return t;
    }

    /**
     * Storage for a full mip chain without data (levels 0 .. log2(max(width, height))), to be filled with
     * {@link #upload} level by level, or level 0 then {@link #generateMipmaps()}.
     */
    public static Texture2D withMips(GlContext gl, int width, int height, Format format, Sampling sampling) {
        Texture2D t = new Texture2D(gl, width, height, format, sampling);
        t.allocate(fullChain(width, height));
        return t;
    }

    private void allocate(int levels) {
        for (int level = 0; level < levels; level++) {
            glTexImage2D(GL_TEXTURE_2D, level, format().internalFormat(), Math.max(1, width() >> level),
                    Math.max(1, height() >> level), 0, format().format(), format().type(), (ByteBuffer) null);
        }
        setLevels(levels);
        stored(levels);
    }

    /**
     * Writes rows {@code y .. y + rows - 1} of one mip level; {@code data} holds {@code rows} full rows in this
     * texture's {@link Format#format()} and {@link Format#type()} (floats or bytes). Large maps upload in strips, so
     * the staging buffer stays small.
     */
    public void upload(int level, int y, int rows, Buffer data) {
        bindForUpdate();
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        int levelWidth = Math.max(1, width() >> level);
        Format f = format();
        if (data instanceof FloatBuffer floats) {
            glTexSubImage2D(GL_TEXTURE_2D, level, 0, y, levelWidth, rows, f.format(), f.type(), floats);
        } else if (data instanceof ByteBuffer bytes) {
            glTexSubImage2D(GL_TEXTURE_2D, level, 0, y, levelWidth, rows, f.format(), f.type(), bytes);
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
}

package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL30C.*;

import java.nio.ByteBuffer;

/**
 * A 2D texture with its size and format, created empty as a render target. Systems that upload data (height maps,
 * synthesised textures) add the factory they need here.
 */
public final class Texture2D implements AutoCloseable {

    /** Sampling and wrap, chosen per use. */
    public record Sampling(int minFilter, int magFilter, int wrap) {
        public static final Sampling NEAREST_CLAMP = new Sampling(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE);
    }

    /** The three numbers GL needs for a pixel format, e.g. RGBA8 = (GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE). */
    public record Format(int internalFormat, int format, int type) {
        public static final Format RGBA8 = new Format(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE);
        public static final Format DEPTH24_STENCIL8 = new Format(GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8);
        public static final Format DEPTH32F = new Format(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT);
    }

    private final GlContext gl;
    private final int width;
    private final int height;
    private final Format format;
    private int id;

    private Texture2D(GlContext gl, int width, int height, Format format, Sampling sampling) {
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("texture size must be positive, got " + width + "x" + height);
        }
        this.gl = gl;
        this.width = width;
        this.height = height;
        this.format = format;
        this.id = glGenTextures();
        gl.objects().created(GlObjects.Kind.TEXTURE);
        glBindTexture(GL_TEXTURE_2D, id);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, sampling.minFilter());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, sampling.magFilter());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, sampling.wrap());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, sampling.wrap());
    }

    /** Storage without data, e.g. a render target. */
    public static Texture2D empty(GlContext gl, int width, int height, Format format, Sampling sampling) {
        Texture2D t = new Texture2D(gl, width, height, format, sampling);
        glTexImage2D(GL_TEXTURE_2D, 0, format.internalFormat(), width, height, 0, format.format(), format.type(),
                (ByteBuffer) null);
        return t;
    }

    /** Binds to texture unit {@code unit}. */
    public void bind(int unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D, id);
    }

    public int id() {
        return id;
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

    @Override
    public void close() {
        if (id != 0) {
            glDeleteTextures(id);
            gl.objects().deleted(GlObjects.Kind.TEXTURE);
            id = 0;
        }
    }
}

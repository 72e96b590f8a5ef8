package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL30C.*;

import java.nio.ByteBuffer;
import org.lwjgl.opengl.GL30C;
import org.lwjgl.system.MemoryUtil;

/**
 * A framebuffer object with texture attachments: optional colour, optional depth (or depth + stencil), which it owns;
 * or one layer of a {@link DepthTextureArray} or of a colour {@link TextureArray}, or level 0 of one or more colour
 * textures that one draw fills at once (e.g. baked once, then mipmapped), which it borrows. The engine's scene target
 * is RGBA8 + depth24/stencil8; the water's reflection is colour + depth; each shadow cascade is a depth layer; the
 * sky's panorama is two colour textures; the unbounded world's sky visibility is written into a clipmap level.
 */
public final class Framebuffer implements Labelled {

    private final GlContext gl;
    private final Texture2D color;
    private final Texture2D depth;
    private final int width;
    private final int height;
    private int id;

    /**
     * @param colorFormat the colour attachment's format, or null for a depth-only target
     * @param depthFormat the depth attachment's format ({@code DEPTH24_STENCIL8} also gives a stencil), or null
     */
    public Framebuffer(GlContext gl, int width, int height, Format colorFormat, Format depthFormat,
                       Sampling sampling) {
        this.gl = gl;
        this.width = width;
        this.height = height;
        this.id = gl.objects().create(GlObjects.Kind.FRAMEBUFFER, GL30C::glGenFramebuffers);
        glBindFramebuffer(GL_FRAMEBUFFER, id);
        color = colorFormat == null ? null : Texture2D.empty(gl, width, height, colorFormat, sampling);
        depth = depthFormat == null ? null : Texture2D.empty(gl, width, height, depthFormat, sampling);
        if (color != null) {
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
        } else {
            glDrawBuffer(GL_NONE);
            glReadBuffer(GL_NONE);
        }
        if (depth != null) {
            int attachment = depthFormat.hasStencil() ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT;
            glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, depth.id(), 0);
        }
        checkComplete();
    }

    /** A depth-only target drawing into one layer of {@code depth}, which stays the caller's to close. */
    private Framebuffer(GlContext gl, DepthTextureArray depth, int layer) {
        this.gl = gl;
        this.width = depth.size();
        this.height = depth.size();
        this.color = null;
        this.depth = null;
        this.id = gl.objects().create(GlObjects.Kind.FRAMEBUFFER, GL30C::glGenFramebuffers);
        glBindFramebuffer(GL_FRAMEBUFFER, id);
        glDrawBuffer(GL_NONE);
        glReadBuffer(GL_NONE);
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, depth.id(), 0, layer);
        checkComplete();
    }

    /** A colour-only target drawing into one layer of {@code colors}, which stays the caller's to close. */
    private Framebuffer(GlContext gl, TextureArray colors, int layer) {
        this.gl = gl;
        this.width = colors.width();
        this.height = colors.height();
        this.color = null;
        this.depth = null;
        this.id = gl.objects().create(GlObjects.Kind.FRAMEBUFFER, GL30C::glGenFramebuffers);
        glBindFramebuffer(GL_FRAMEBUFFER, id);
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, colors.id(), 0, layer);
        checkComplete();
    }

    /** A colour-only target drawing into level 0 of each of {@code colors}, which stay the caller's to close. */
    private Framebuffer(GlContext gl, Texture2D[] colors) {
        this.gl = gl;
        this.width = colors[0].width();
        this.height = colors[0].height();
        this.color = null;
        this.depth = null;
        this.id = gl.objects().create(GlObjects.Kind.FRAMEBUFFER, GL30C::glGenFramebuffers);
        glBindFramebuffer(GL_FRAMEBUFFER, id);
        int[] buffers = new int[colors.length];
        for (int i = 0; i < colors.length; i++) {
            buffers[i] = GL_COLOR_ATTACHMENT0 + i;
            glFramebufferTexture2D(GL_FRAMEBUFFER, buffers[i], GL_TEXTURE_2D, colors[i].id(), 0);
        }
        glDrawBuffers(buffers);
        checkComplete();
    }

    /**
     * A target for level 0 of one or more colour textures of one size (fragment output i to texture i), e.g. to
     * render into textures and then build their mips; closing it leaves the textures alone, and {@link #color()}
     * answers null.
     */
    public static Framebuffer onTextures(GlContext gl, Texture2D... colors) {
        if (colors.length == 0) {
            throw new IllegalArgumentException("a framebuffer on textures needs at least one texture");
        }
        return new Framebuffer(gl, colors);
    }

    /** A target for one layer of a depth array, e.g. one shadow cascade; closing it leaves the array alone. */
    public static Framebuffer onLayer(GlContext gl, DepthTextureArray depth, int layer) {
        if (layer < 0 || layer >= depth.layers()) {
            throw new IllegalArgumentException("layer " + layer + " of a " + depth.layers() + "-layer array");
        }
        return new Framebuffer(gl, depth, layer);
    }

    /**
     * A target for one layer of a colour array, e.g. a level of a clipmap written in place; closing it leaves the
     * array alone.
     */
    public static Framebuffer onLayer(GlContext gl, TextureArray colors, int layer) {
        if (layer < 0 || layer >= colors.layers()) {
            throw new IllegalArgumentException("layer " + layer + " of a " + colors.layers() + "-layer array");
        }
        return new Framebuffer(gl, colors, layer);
    }

    private void checkComplete() {
        int status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (status != GL_FRAMEBUFFER_COMPLETE) {
            close();
            throw new IllegalStateException("framebuffer " + width + "x" + height + " incomplete: status 0x"
                    + Integer.toHexString(status));
        }
    }

    /** The usual scene target: RGBA8 colour and depth24 + stencil8, nearest sampling. */
    public static Framebuffer scene(GlContext gl, int width, int height) {
        return new Framebuffer(gl, width, height, Format.RGBA8, Format.DEPTH24_STENCIL8, Sampling.NEAREST_CLAMP);
    }

    /** Binds for drawing and sets the viewport to the whole target. */
    public void bind() {
        glBindFramebuffer(GL_FRAMEBUFFER, id);
        glViewport(0, 0, width(), height());
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

    /** The owned colour attachment; null for a depth-only target or one on a borrowed texture. */
    public Texture2D color() {
        return color;
    }

    /** The owned depth attachment; null for a depth-only target on a layer of a {@link DepthTextureArray}. */
    public Texture2D depth() {
        return depth;
    }

    /** Reads the colour attachment back into an image, top row first. Waits for the GPU. */
    public Image read() {
        int w = width();
        int h = height();
        ByteBuffer pixels = MemoryUtil.memAlloc(w * h * 4);
        try {
            glBindFramebuffer(GL_READ_FRAMEBUFFER, id);
            glReadBuffer(GL_COLOR_ATTACHMENT0);
            glPixelStorei(GL_PACK_ALIGNMENT, 1);
            glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
            glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
            return Image.fromBottomUp(w, h, pixels);
        } finally {
            MemoryUtil.memFree(pixels);
        }
    }

    /** Copies the colour into the window's default framebuffer, scaled to fill it. */
    public void blitToScreen(int screenWidth, int screenHeight) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, id);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        glBlitFramebuffer(0, 0, width(), height(), 0, 0, screenWidth, screenHeight, GL_COLOR_BUFFER_BIT, GL_LINEAR);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    /** Names the framebuffer and its own attachments, {@code name.color} and {@code name.depth}. */
    @Override
    public void label(String name) {
        gl.debug().label(GL_FRAMEBUFFER, id, name);
        if (color != null) {
            color.label(name + ".color");
        }
        if (depth != null) {
            depth.label(name + ".depth");
        }
    }

    @Override
    public void close() {
        if (color != null) {
            color.close();
        }
        if (depth != null) {
            depth.close();
        }
        id = gl.objects().delete(GlObjects.Kind.FRAMEBUFFER, id, GL30C::glDeleteFramebuffers);
    }
}

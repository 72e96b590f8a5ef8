package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL30C.*;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;
import org.lwjgl.opengl.GL30C;
import org.lwjgl.system.MemoryUtil;

/**
 * A framebuffer object with texture attachments: optional colour, optional depth (or depth + stencil), which it owns;
 * or one layer of a {@link DepthTextureArray}, which it borrows; or several colour targets that one draw fills at
 * once ({@link #colors}). The engine's scene target is RGBA8 + depth24/stencil8; the water's reflection is colour +
 * depth; each shadow cascade is a depth layer; the sky's panorama is two colour targets.
 */
public final class Framebuffer implements Labelled {

    private final GlContext gl;
    private final List<Texture2D> colors = new ArrayList<>();
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
        if (colorFormat != null) {
            colors.add(Texture2D.empty(gl, width, height, colorFormat, sampling));
        }
        depth = depthFormat == null ? null : Texture2D.empty(gl, width, height, depthFormat, sampling);
        if (colorFormat != null) {
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colors.get(0).id(), 0);
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
        this.depth = null;
        this.id = gl.objects().create(GlObjects.Kind.FRAMEBUFFER, GL30C::glGenFramebuffers);
        glBindFramebuffer(GL_FRAMEBUFFER, id);
        glDrawBuffer(GL_NONE);
        glReadBuffer(GL_NONE);
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, depth.id(), 0, layer);
        checkComplete();
    }

    /**
     * {@code count} colour targets of one format and no depth: a fragment shader's output {@code layout(location = i)}
     * goes to {@link #color(int) color(i)}, all in one draw.
     */
    public static Framebuffer colors(GlContext gl, int width, int height, int count, Format format,
                                     Sampling sampling) {
        Framebuffer f = new Framebuffer(gl, width, height, format, null, sampling);
        glBindFramebuffer(GL_FRAMEBUFFER, f.id);
        int[] buffers = new int[count];
        buffers[0] = GL_COLOR_ATTACHMENT0;
        for (int i = 1; i < count; i++) {
            f.colors.add(Texture2D.empty(gl, width, height, format, sampling));
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + i, GL_TEXTURE_2D, f.colors.get(i).id(), 0);
            buffers[i] = GL_COLOR_ATTACHMENT0 + i;
        }
        glDrawBuffers(buffers);
        f.checkComplete();
        return f;
    }

    /** A target for one layer of a depth array, e.g. one shadow cascade; closing it leaves the array alone. */
    public static Framebuffer onLayer(GlContext gl, DepthTextureArray depth, int layer) {
        if (layer < 0 || layer >= depth.layers()) {
            throw new IllegalArgumentException("layer " + layer + " of a " + depth.layers() + "-layer array");
        }
        return new Framebuffer(gl, depth, layer);
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

    /** The (first) colour attachment; null for a depth-only target. */
    public Texture2D color() {
        return colors.isEmpty() ? null : colors.get(0);
    }

    /** Colour attachment {@code i} of a target made by {@link #colors}. */
    public Texture2D color(int i) {
        return colors.get(i);
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
        for (int i = 0; i < colors.size(); i++) {
            colors.get(i).label(name + ".color" + (i == 0 ? "" : String.valueOf(i)));
        }
        if (depth != null) {
            depth.label(name + ".depth");
        }
    }

    @Override
    public void close() {
        colors.forEach(Texture2D::close);
        if (depth != null) {
            depth.close();
        }
        id = gl.objects().delete(GlObjects.Kind.FRAMEBUFFER, id, GL30C::glDeleteFramebuffers);
    }
}

package org.openworld.demo;

import static org.lwjgl.opengl.GL11C.GL_MAX_TEXTURE_SIZE;
import static org.lwjgl.opengl.GL11C.glGetInteger;
import static org.lwjgl.opengl.GL30C.GL_MAX_RENDERBUFFER_SIZE;

import java.util.Locale;
import picocli.CommandLine;
import picocli.CommandLine.ITypeConverter;

/**
 * A render size in pixels, written WxH on the command line, and the checks that a size can be rendered at all, made
 * up front: a size too large for memory or for the OpenGL at hand would otherwise run for minutes and gigabytes
 * before failing, or fail with a driver's incomplete-framebuffer status.
 *
 * <p>The memory estimate counts the targets that grow with the size, {@link #BYTES_PER_PIXEL} bytes a pixel: the
 * scene's RGBA8 colour and 24+8-bit depth and stencil (8), the water's copy of both to look through (8), and its
 * reflection target at most at full size (8). Shadow maps, the sky's tables and the terrain's textures do not grow
 * with the size and are left out, as is the read-back copy on the Java heap (8 bytes a pixel for a shot), so the
 * estimate is a floor, right to within tens of percent for large sizes.
 */
record Size(int width, int height) {

    /** Largest side accepted, pixels (GL_MAX_TEXTURE_SIZE on most hardware is 16384). */
    static final int MAX_SIDE = 16384;

    /** Bytes of render targets per pixel of the picture; see the class comment. */
    static final int BYTES_PER_PIXEL = 24;

    /** Largest render-target memory accepted: 4 GiB, more than most GPUs can spare beside the world. */
    static final long MAX_TARGET_BYTES = 4L << 30;

    private static final double BYTES_PER_GIB = 1024.0 * 1024.0 * 1024.0;

    /** The render targets' estimated memory, bytes. */
    long targetBytes() {
        return (long) width * height * BYTES_PER_PIXEL;
    }

    /** Refuses a size whose render targets would exceed {@link #MAX_TARGET_BYTES}, with the estimate. */
    void checkMemory() {
        if (targetBytes() > MAX_TARGET_BYTES) {
            throw new UserError(String.format(Locale.ROOT, "--size %dx%d: the render targets need about %.1f GiB "
                    + "(%d bytes a pixel: the scene, the water's copy of it and its reflection), more than the %.0f "
                    + "GiB allowed; use a smaller size, e.g. 7680x4320", width, height, targetBytes() / BYTES_PER_GIB,
                    BYTES_PER_PIXEL, MAX_TARGET_BYTES / BYTES_PER_GIB));
        }
    }

    /** Refuses a size with a side over this OpenGL's largest texture or renderbuffer; needs a current context. */
    void checkGlLimits() {
        checkSide(Math.min(glGetInteger(GL_MAX_TEXTURE_SIZE), glGetInteger(GL_MAX_RENDERBUFFER_SIZE)));
    }

    /** Refuses a size with a side over {@code maxSide}, the OpenGL's largest render target, pixels. */
    void checkSide(int maxSide) {
        if (width > maxSide || height > maxSide) {
            throw new UserError("--size " + width + "x" + height + ": this OpenGL's render targets are at most "
                    + maxSide + " pixels a side (GL_MAX_TEXTURE_SIZE, GL_MAX_RENDERBUFFER_SIZE)");
        }
    }

    static final class Converter implements ITypeConverter<Size> {
        @Override
        public Size convert(String text) {
            String[] parts = text.toLowerCase(java.util.Locale.ROOT).split("x");
            try {
                if (parts.length == 2) {
                    int w = Integer.parseInt(parts[0].trim());
                    int h = Integer.parseInt(parts[1].trim());
                    if (w >= 1 && h >= 1 && w <= MAX_SIDE && h <= MAX_SIDE) {
                        return new Size(w, h);
                    }
                }
            } catch (NumberFormatException e) {
                // fall through to the message below
            }
            throw new CommandLine.TypeConversionException("'" + text + "': expected WIDTHxHEIGHT in pixels, each 1.."
                    + MAX_SIDE + ", e.g. 1280x720");
        }
    }
}

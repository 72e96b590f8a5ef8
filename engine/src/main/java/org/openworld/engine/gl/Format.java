package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL30C.*;

/**
 * A texel format: the three numbers GL needs to make and fill a texture, e.g. RGBA8 is {@code (GL_RGBA8, GL_RGBA,
 * GL_UNSIGNED_BYTE)}: how the GPU stores a texel ({@link #internalFormat()}), and the layout ({@link #format()}) and
 * element type ({@link #type()}) of the data handed to an upload. One list for every texture class and
 * {@link Framebuffer}: a half-float format is filled from floats, the driver converts.
 */
public enum Format {
    /** Four bytes, linear: colour targets and data maps. */
    RGBA8(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE),
    /** sRGB-encoded colour with linear alpha: sampling decodes to linear light, mipmaps average in linear light. */
    SRGB8_ALPHA8(GL_SRGB8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE),
    /** One byte per texel, e.g. a coverage mask. */
    R8(GL_R8, GL_RED, GL_UNSIGNED_BYTE),
    /** Two bytes per texel, e.g. two coverages read by one lookup. */
    RG8(GL_RG8, GL_RG, GL_UNSIGNED_BYTE),
    /** One float per texel, e.g. heights in metres. */
    R32F(GL_R32F, GL_RED, GL_FLOAT),
    /** One half float per texel, uploaded from floats, e.g. a cloud density field. */
    R16F(GL_R16F, GL_RED, GL_FLOAT),
    /** Two half floats per texel, uploaded from floats, e.g. a height gradient. */
    RG16F(GL_RG16F, GL_RG, GL_FLOAT),
    /** Three half floats per texel, uploaded from floats, e.g. radiance that may exceed 1. */
    RGB16F(GL_RGB16F, GL_RGB, GL_FLOAT),
    /** Four half floats per texel, uploaded from floats, e.g. a table of linear colours above 1. */
    RGBA16F(GL_RGBA16F, GL_RGBA, GL_FLOAT),
    /** Four full floats per texel: values read back exactly (a probe of positions). */
    RGBA32F(GL_RGBA32F, GL_RGBA, GL_FLOAT),
    /** 24-bit depth and an 8-bit stencil: the scene's depth, with the water's stencil marks. */
    DEPTH24_STENCIL8(GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8),
    /** 32-bit float depth: shadow maps and depth that is read back. */
    DEPTH32F(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT),
    /**
     * 24-bit fixed-point depth, uploaded from floats: 2^24 equal steps over 0 .. 1, the paper's shadow-map depth
     * ({@code shadow.depth=fixed24}).
     */
    DEPTH24(GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_FLOAT);

    private final int internalFormat;
    private final int format;
    private final int type;

    Format(int internalFormat, int format, int type) {
        this.internalFormat = internalFormat;
        this.format = format;
        this.type = type;
    }

    /** How the GPU stores a texel, e.g. {@code GL_RGBA8}. */
    public int internalFormat() {
        return internalFormat;
    }

    /** The layout of uploaded data, e.g. {@code GL_RGBA}. */
    public int format() {
        return format;
    }

    /** The element type of uploaded data, e.g. {@code GL_FLOAT}. */
    public int type() {
        return type;
    }

    /** Values per texel in uploaded data: 1 red, 2 RG, 3 RGB, 4 RGBA, 1 for depth, 1 packed depth + stencil. */
    public int components() {
        return switch (format) {
            case GL_RG -> 2;
            case GL_RGB -> 3;
            case GL_RGBA -> 4;
            default -> 1;
        };
    }

    /** Whether a framebuffer attaches it as depth and stencil rather than depth alone or colour. */
    public boolean hasStencil() {
        return format == GL_DEPTH_STENCIL;
    }

    /** Whether it is a depth format (attached as depth, not colour). */
    public boolean isDepth() {
        return format == GL_DEPTH_COMPONENT || format == GL_DEPTH_STENCIL;
    }
}

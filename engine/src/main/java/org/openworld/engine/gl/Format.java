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
    RGBA8(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4),
    /** sRGB-encoded colour with linear alpha: sampling decodes to linear light, mipmaps average in linear light. */
    SRGB8_ALPHA8(GL_SRGB8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE, 4),
    /** One byte per texel, e.g. a coverage mask. */
    R8(GL_R8, GL_RED, GL_UNSIGNED_BYTE, 1),
    /** Two bytes per texel, e.g. two coverages read by one lookup. */
    RG8(GL_RG8, GL_RG, GL_UNSIGNED_BYTE, 2),
    /** One float per texel, e.g. heights in metres. */
    R32F(GL_R32F, GL_RED, GL_FLOAT, 4),
    /** One half float per texel, uploaded from floats, e.g. a cloud density field. */
    R16F(GL_R16F, GL_RED, GL_FLOAT, 2),
    /** Two half floats per texel, uploaded from floats, e.g. a height gradient. */
    RG16F(GL_RG16F, GL_RG, GL_FLOAT, 4),
    /**
     * Three half floats per texel, uploaded from floats, e.g. radiance that may exceed 1. Counted as its 6 bytes;
     * many GPUs pad it to four channels (8 bytes) in memory.
     */
    RGB16F(GL_RGB16F, GL_RGB, GL_FLOAT, 6),
    /** Four half floats per texel, uploaded from floats, e.g. a table of linear colours above 1. */
    RGBA16F(GL_RGBA16F, GL_RGBA, GL_FLOAT, 8),
    /** Two 32-bit signed integers per texel, read with texelFetch from an integer sampler, e.g. a pair of indices. */
    RG32I(GL_RG32I, GL_RG_INTEGER, GL_INT, 8),
    /** Three full floats per texel: radiance over the night's range, below what a half float holds (6·10⁻⁵). */
    RGB32F(GL_RGB32F, GL_RGB, GL_FLOAT, 12),
    /** Four full floats per texel: values read back exactly (a probe of positions). */
    RGBA32F(GL_RGBA32F, GL_RGBA, GL_FLOAT, 16),
    /** 24-bit depth and an 8-bit stencil: the scene's depth, with the water's stencil marks. */
    DEPTH24_STENCIL8(GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, 4),
    /** 32-bit float depth: shadow maps and depth that is read back. */
    DEPTH32F(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, 4),
    /**
     * 24-bit fixed-point depth, uploaded from floats: 2^24 equal steps over 0 .. 1, the paper's shadow-map depth
     * ({@code shadow.depth=fixed24}). Counted as 4 bytes a texel, as drivers store it: 24 bits in a 32-bit word.
     */
    DEPTH24(GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_FLOAT, 4);

    private final int internalFormat;
    private final int format;
    private final int type;
    private final int bytesPerTexel;

    Format(int internalFormat, int format, int type, int bytesPerTexel) {
        this.internalFormat = internalFormat;
        this.format = format;
        this.type = type;
        this.bytesPerTexel = bytesPerTexel;
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

    /**
     * Bytes one texel takes in GPU memory, counted in {@link TextureMemory}: the sum of the internal format's
     * channels (RG16F: 2 × 2), except {@link #DEPTH24}, stored in 4 like {@link #DEPTH24_STENCIL8}. Not the size of
     * uploaded data, which may be floats for a half-float format.
     */
    public int bytesPerTexel() {
        return bytesPerTexel;
    }

    /** Values per texel in uploaded data: 1 red, 2 RG, 3 RGB, 4 RGBA, 1 for depth, 1 packed depth + stencil. */
    public int components() {
        return switch (format) {
            case GL_RG, GL_RG_INTEGER -> 2;
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

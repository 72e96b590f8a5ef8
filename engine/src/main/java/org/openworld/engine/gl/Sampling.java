package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL30C.*;

/**
 * How a texture is filtered and what lies beyond its edges, the same on every axis (s, t and, for volumes and cube
 * maps, r): one record for every texture class, written into the texture once by {@link GlTexture}. A mipmapped
 * minification filter ({@code GL_*_MIPMAP_*}) needs the texture to have its mip levels.
 *
 * @param minFilter {@code GL_TEXTURE_MIN_FILTER}, e.g. {@code GL_LINEAR_MIPMAP_LINEAR}
 * @param magFilter {@code GL_TEXTURE_MAG_FILTER}, {@code GL_NEAREST} or {@code GL_LINEAR}
 * @param wrap      {@code GL_TEXTURE_WRAP_S/T/R}, e.g. {@code GL_REPEAT} or {@code GL_CLAMP_TO_EDGE}
 */
public record Sampling(int minFilter, int magFilter, int wrap) {
    /** Exact texels, clamped at the edges: render targets read one texel per pixel. */
    public static final Sampling NEAREST_CLAMP = new Sampling(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE);
    /**
     * Exact texels, the border beyond the edges: a shadow map, whose border {@link DepthTextureArray} sets to the far
     * plane, so a point outside the map reads as lit.
     */
    public static final Sampling NEAREST_BORDER = new Sampling(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_BORDER);
    /** Bilinear (trilinear in a volume), clamped at the edges: a look-up table read between its texels. */
    public static final Sampling LINEAR_CLAMP = new Sampling(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    /** Bilinear (trilinear in a volume), wrapping: a field periodic along every axis. */
    public static final Sampling LINEAR_REPEAT = new Sampling(GL_LINEAR, GL_LINEAR, GL_REPEAT);
    /** Exact texels by {@code texelFetch} from every mip level (a height pyramid). */
    public static final Sampling NEAREST_MIPMAP = new Sampling(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, GL_REPEAT);
    /** Trilinear and tiling: a map that wraps around (a periodic world, a tiling material). */
    public static final Sampling TRILINEAR_REPEAT = new Sampling(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT);
    /** Trilinear and clamped at the edges (an imported, non-periodic map; a cube map's faces). */
    public static final Sampling TRILINEAR_CLAMP = new Sampling(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
}

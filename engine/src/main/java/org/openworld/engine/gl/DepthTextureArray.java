package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL30C.*;

import java.nio.FloatBuffer;
import org.lwjgl.system.MemoryUtil;

/**
 * Square depth layers sampled by comparison ({@code sampler2DArrayShadow} in GLSL): the sun's shadow maps, one layer
 * per cascade. A lookup {@code texture(map, vec4(uv, layer, depth))} answers 1 where the stored depth is at least
 * {@code depth} (nothing between the point and the sun) and 0 where it is nearer; nearest filtering, so each lookup
 * is one texel's yes or no and any softening is the reader's own filter (the paper's PCF). Outside the map the
 * border depth 1 answers "lit". Each layer is drawn through its own {@link Framebuffer#onLayer}.
 */
public final class DepthTextureArray extends GlTexture {

    private DepthTextureArray(GlContext gl, int size, int layers, Format format, FloatBuffer depths) {
        super(gl, GL_TEXTURE_2D_ARRAY, size, size, layers, format, Sampling.NEAREST_BORDER);
        if (format != Format.DEPTH32F && format != Format.DEPTH24) {
            throw new IllegalArgumentException("a shadow map holds depth alone, not " + format);
        }
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, format().internalFormat(), size, size, layers, 0, format().format(),
                format().type(), depths);
        glTexParameterfv(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BORDER_COLOR, new float[] {1, 1, 1, 1});
        setLevels(1);
        stored(1);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    }

    /**
     * Storage for {@code layers} maps of {@code size}² depths, to be drawn into.
     *
     * @param size   texels per side
     * @param layers maps, one per cascade
     * @param format {@link Format#DEPTH32F} (32-bit float) or {@link Format#DEPTH24} (24-bit fixed point, the
     *               paper's)
     */
    public static DepthTextureArray of(GlContext gl, int size, int layers, Format format) {
        return new DepthTextureArray(gl, size, layers, format, null);
    }

    /** One texel at the far plane (depth 1): a map with nothing in it, under which everything is lit. */
    public static DepthTextureArray empty(GlContext gl) {
        FloatBuffer far = MemoryUtil.memAllocFloat(1).put(0, 1f);
        try {
            return new DepthTextureArray(gl, 1, 1, Format.DEPTH32F, far);
        } finally {
            MemoryUtil.memFree(far);
        }
    }

    /**
     * Reads every layer back (waits for the GPU): {@code size² · layers} depths in 0 .. 1, row by row from v = 0,
     * layer after layer. For tests and tools.
     */
    public float[] read() {
        FloatBuffer depths = MemoryUtil.memAllocFloat(size() * size() * layers());
        try {
            bindForUpdate();
            glPixelStorei(GL_PACK_ALIGNMENT, 4);
            glGetTexImage(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
            float[] out = new float[depths.remaining()];
            depths.get(out);
            return out;
        } finally {
            MemoryUtil.memFree(depths);
        }
    }

    /** Texels along a map's side. */
    public int size() {
        return width();
    }

    /** Maps, one per cascade. */
    public int layers() {
        return depth();
    }
}

package org.openworld.engine.terrain.material;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.Texture2D;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.HeightPyramid;
import org.openworld.engine.terrain.heights.StageTimes;

/**
 * The terrain's maps on the GPU, each sampled where the world position says:
 * <ul>
 *   <li>{@code heights}: the height pyramid as one R32F texture whose mip level k <em>is</em> pyramid level k, read
 *       exactly with {@code texelFetch} by the vertex shader (a patch of level L reads level L);</li>
 *   <li>{@code gradients}: (∂h/∂x, ∂h/∂z) of level 0 by central differences, RG16F with box-filtered mips. A
 *       gradient averages correctly under filtering (a normal would not), so distant coarse patches still shade
 *       with the slope of every sample beneath them;</li>
 *   <li>{@code snow}: r the snow map's coverage, blurred by {@value #SNOW_BLUR_PASSES} binomial passes (a Gaussian
 *       of σ ≈ 1.7 texels) before upload: the 0/1 map's texel squares would otherwise show as blocks close up, and
 *       the blur turns them into soft drifts that the material's threshold shapes; g the share of the sky the
 *       relief leaves each place ({@link TileSky}, baked on the GPU from the heights), resampled to the snow map's
 *       grid; b and a what the erosion left, the sediment's cover and 1 − the bared bed's ({@link ErosionCover}).
 *       RGBA8 with mips: the material reads all four with the one lookup it already made for the snow.</li>
 * </ul>
 * Periodic maps repeat; imported ones clamp. Uploads go in strips of rows, so an 8192² map needs a staging buffer
 * of a few megabytes, not of the whole map.
 */
public final class TerrainMaps {

    /** Passes of the (1 4 6 4 1)/16 kernel over the snow map; variances add, σ = √(passes · 1) texels. */
    public static final int SNOW_BLUR_PASSES = 3;
    /** Rows uploaded per call: bounds the staging buffer at 8192 × 64 × 2 floats = 4 MiB. */
    private static final int STRIP_ROWS = 64;

    public final Texture2D heights;
    public final Texture2D gradients;
    public final Texture2D snow;

    /** The stage that bakes the sky's visibility, as {@link StageTimes} records it. */
    public static final String SKY_VIEW = "sky view";

    /**
     * Makes and fills the three maps, handed to the system's owner as {@code terrain.heights}, ...; the sky's
     * visibility is baked with the heights bound to {@code unit}, timed into {@code times}; {@code sediment} is the
     * erosion's change ({@link ErosionCover}), or null.
     */
    public TerrainMaps(EngineContext context, HeightPyramid pyramid, SnowMap snowMap, HeightMap sediment, int unit,
                       StageTimes times) {
        GlContext gl = context.gl();
        HeightMap base = pyramid.base();
        Sampling wrap = base.periodic() ? Sampling.TRILINEAR_REPEAT : Sampling.TRILINEAR_CLAMP;
        heights = context.own("heights",
                Texture2D.withMips(gl, base.size(), base.size(), Format.R32F, Sampling.NEAREST_MIPMAP));
        for (int k = 0; k < pyramid.levelCount(); k++) {
            uploadHeights(heights, k, pyramid.level(k));
        }
        gradients = context.own("gradients", Texture2D.withMips(gl, base.size(), base.size(), Format.RG16F, wrap));
        uploadGradients(gradients, base);
        gradients.generateMipmaps();
        int n = snowMap.size();
        snow = context.own("snow", Texture2D.withMips(gl, n, n, Format.RGBA8, wrap));
        byte[] soft = blur(snowMap.coverage(), n, snowMap.periodic());
        TileSky sky = times.time(SKY_VIEW, () -> TileSky.bake(gl, context.shaders(), heights, pyramid, unit));
        byte[] visible = sky.resampled(n);
        byte[][] cover = ErosionCover.of(sediment, n);
        ByteBuffer texels = MemoryUtil.memAlloc(4 * soft.length);
        try {
            for (int i = 0; i < soft.length; i++) {
                texels.put(soft[i]).put(visible[i]).put(cover[0][i]).put(cover[1][i]);
            }
            snow.upload(0, 0, n, texels.flip());
        } finally {
            MemoryUtil.memFree(texels);
        }
        snow.generateMipmaps();
    }

    /** The coverage low-passed along rows and then columns, {@link #SNOW_BLUR_PASSES} times, wrapping or clamping. */
    public static byte[] blur(byte[] coverage, int size, boolean periodic) {
        float[] a = new float[coverage.length];
        for (int i = 0; i < a.length; i++) {
            a[i] = coverage[i] & 0xFF;
        }
        float[] b = new float[a.length];
        for (int pass = 0; pass < SNOW_BLUR_PASSES; pass++) {
            binomial(a, b, size, 1, size, periodic);
            binomial(b, a, size, size, 1, periodic);
        }
        byte[] out = new byte[a.length];
        for (int i = 0; i < a.length; i++) {
            out[i] = (byte) Math.round(a[i]);
        }
        return out;
    }

    /** One (1 4 6 4 1)/16 pass: {@code step} between taps, {@code lineStep} between the lines filtered. */
    private static void binomial(float[] from, float[] to, int size, int step, int lineStep, boolean periodic) {
        final float[] weights = {1 / 16f, 4 / 16f, 6 / 16f, 4 / 16f, 1 / 16f};
        for (int line = 0; line < size; line++) {
            int base = line * lineStep;
            for (int i = 0; i < size; i++) {
                float sum = 0;
                for (int t = -2; t <= 2; t++) {
                    int j = periodic ? (i + t) & (size - 1) : Math.max(0, Math.min(size - 1, i + t));
                    sum += weights[t + 2] * from[base + j * step];
                }
                to[base + i * step] = sum;
            }
        }
    }

    private static void uploadHeights(Texture2D texture, int level, HeightMap map) {
        int n = map.size();
        int rows = Math.min(STRIP_ROWS, n);
        FloatBuffer strip = MemoryUtil.memAllocFloat(n * rows);
        try {
            for (int y = 0; y < n; y += rows) {
                strip.clear();
                strip.put(map.heights(), y * n, n * rows).flip();
                texture.upload(level, y, rows, strip);
            }
        } finally {
            MemoryUtil.memFree(strip);
        }
    }

    private static void uploadGradients(Texture2D texture, HeightMap map) {
        int n = map.size();
        int rows = Math.min(STRIP_ROWS, n);
        float inv2d = (float) (1 / (2 * map.spacing()));
        FloatBuffer strip = MemoryUtil.memAllocFloat(2 * n * rows);
        try {
            for (int y = 0; y < n; y += rows) {
                strip.clear();
                for (int z = y; z < y + rows; z++) {
                    for (int x = 0; x < n; x++) {
                        strip.put((map.sample(x + 1, z) - map.sample(x - 1, z)) * inv2d);
                        strip.put((map.sample(x, z + 1) - map.sample(x, z - 1)) * inv2d);
                    }
                }
                strip.flip();
                texture.upload(0, y, rows, strip);
            }
        } finally {
            MemoryUtil.memFree(strip);
        }
    }
}

package org.openworld.engine.terrain;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Texture2D;

/**
 * The terrain's maps on the GPU, each sampled where the world position says:
 * <ul>
 *   <li>{@code heights}: the height pyramid as one R32F texture whose mip level k <em>is</em> pyramid level k, read
 *       exactly with {@code texelFetch} by the vertex shader (a patch of level L reads level L);</li>
 *   <li>{@code gradients}: (∂h/∂x, ∂h/∂z) of level 0 by central differences, RG16F with box-filtered mips. A
 *       gradient averages correctly under filtering (a normal would not), so distant coarse patches still shade
 *       with the slope of every sample beneath them;</li>
 *   <li>{@code snow}: the snow map's coverage, R8 with mips, filtered to soften its edges.</li>
 * </ul>
 * Periodic maps repeat; imported ones clamp. Uploads go in strips of rows, so an 8192² map needs a staging buffer
 * of a few megabytes, not of the whole map.
 */
final class TerrainMaps implements AutoCloseable {

    /** Rows uploaded per call: bounds the staging buffer at 8192 × 64 × 2 floats = 4 MiB. */
    private static final int STRIP_ROWS = 64;

    final Texture2D heights;
    final Texture2D gradients;
    final Texture2D snow;

    TerrainMaps(GlContext gl, HeightPyramid pyramid, SnowMap snowMap) {
        HeightMap base = pyramid.base();
        Texture2D.Sampling wrap = base.periodic() ? Texture2D.Sampling.TRILINEAR_REPEAT : Texture2D.Sampling.TRILINEAR_CLAMP;
        Texture2D h = null;
        Texture2D g = null;
        Texture2D s = null;
        try {
            h = Texture2D.withMips(gl, base.size(), base.size(), Texture2D.Format.R32F, Texture2D.Sampling.NEAREST_MIPMAP);
            for (int k = 0; k < pyramid.levelCount(); k++) {
                uploadHeights(h, k, pyramid.level(k));
            }
            g = Texture2D.withMips(gl, base.size(), base.size(), Texture2D.Format.RG16F, wrap);
            uploadGradients(g, base);
            g.generateMipmaps();
            s = Texture2D.withMips(gl, snowMap.size(), snowMap.size(), Texture2D.Format.R8, wrap);
            ByteBuffer coverage = MemoryUtil.memAlloc(snowMap.coverage().length).put(snowMap.coverage()).flip();
            try {
                s.upload(0, 0, snowMap.size(), coverage);
            } finally {
                MemoryUtil.memFree(coverage);
            }
            s.generateMipmaps();
        } catch (RuntimeException e) {
            for (Texture2D t : new Texture2D[] {s, g, h}) {
                if (t != null) {
                    t.close();
                }
            }
            throw e;
        }
        heights = h;
        gradients = g;
        snow = s;
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

    @Override
    public void close() {
        snow.close();
        gradients.close();
        heights.close();
    }
}

package org.openworld.engine.terrain.material;

import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Image;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.OffscreenState;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.ShaderLibrary;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Texture2D;
import org.openworld.engine.terrain.heights.HeightPyramid;

/**
 * The tile's share of the sky seen ({@link HorizonSearch}), made on the GPU when the world is built, as the streamed
 * world's blocks make theirs: {@code shaders/terrain/material/tilesky.frag} runs the search for every sample of the
 * first pyramid level of at most {@value #MAX_SIZE}² samples (8 m apart on the default map: occlusion varies over tens of
 * metres), reading the pyramid's levels from the height texture's mips, wrapped on a periodic tile. The tile is one
 * block: one full-screen triangle over an R8 target of that level's size, read back and resampled to the snow map's
 * grid, whose texture carries it in g ({@link TerrainMaps}).
 *
 * <p>Cost: {@code 8 · log(3000 m / d) / log 1.4} bilinear reads per sample, 8 × 19 for 512² at 8 m: one draw,
 * 2.0–2.4 s on llvmpipe on a loaded two-core machine (the same search on the CPU took 2.8–2.9 s there), and a 256 KiB
 * read-back. Limits: those of the search ({@link HorizonSearch}); the map is read back and resampled on the CPU.
 */
public final class TileSky {

    /** Largest side of the map, samples. */
    public static final int MAX_SIZE = 512;

    private final int size;
    private final boolean periodic;
    private final byte[] values;

    private TileSky(int size, boolean periodic, byte[] values) {
        this.size = size;
        this.periodic = periodic;
        this.values = values;
    }

    /**
     * The visibility of {@code pyramid}, whose levels are the mips of {@code heights}, bound to {@code unit} for the
     * pass. Leaves the framebuffer, viewport and tests as they were; the program in use changes.
     */
    public static TileSky bake(GlContext gl, ShaderLibrary shaders, Texture2D heights, HeightPyramid pyramid,
                               int unit) {
        int level = 0;
        while (pyramid.level(level).size() > MAX_SIZE) {
            level++;
        }
        int n = pyramid.level(level).size();
        boolean periodic = pyramid.base().periodic();
        try (ShaderProgram program = shaders.program(HorizonSearch.defines(pyramid.spacing(level)),
                "terrain/material/bake.vert", "terrain/material/tilesky.frag");
             Mesh triangle = Mesh.fullScreenTriangle(gl);
             OffscreenState state = OffscreenState.enter();
             Framebuffer target = new Framebuffer(gl, n, n, Format.R8, null, Sampling.NEAREST_CLAMP)) {
            program.use();
            HorizonSearch.Uniforms search = new HorizonSearch.Uniforms(program, pyramid.levelCount(),
                    pyramid.spacing(0), pyramid.spacing(level));
            program.sampler("heights", unit);
            program.int1("mapSize").set(pyramid.base().size());
            program.int1("periodic").set(periodic ? 1 : 0);
            search.set(level, pyramid.levelCount(), pyramid::spacing);
            heights.bind(unit); // after the target, whose texture was bound to the active unit as it was made
            target.bind();
            triangle.draw(new DrawStats());
            Image image = target.read();
            byte[] values = new byte[n * n];
            for (int row = 0; row < n; row++) {
                for (int col = 0; col < n; col++) {
                    values[row * n + col] = (byte) image.channel(col, n - 1 - row, 0);
                }
            }
            return new TileSky(n, periodic, values);
        }
    }

    /** Samples per side. */
    public int size() {
        return size;
    }

    /** The visibility at (col, row), 0..1 in steps of 1/255, wrapped or clamped like the heights. */
    public double visibleAt(int col, int row) {
        return raw(col, row) / 255.0;
    }

    /**
     * The visibility at the samples of a map of the same extent, {@code n} at least this map's samples per side (a
     * power-of-two multiple), interpolated bilinearly: sample i of the finer map lies at coordinate i / f of this one.
     */
    public byte[] resampled(int n) {
        int f = n / size;
        if (f * size != n) {
            throw new IllegalArgumentException("resampling " + size + " samples to " + n);
        }
        byte[] out = new byte[n * n];
        for (int row = 0; row < n; row++) {
            int r0 = row / f;
            float fz = (float) (row % f) / f;
            for (int col = 0; col < n; col++) {
                int c0 = col / f;
                float fx = (float) (col % f) / f;
                float top = raw(c0, r0) + (raw(c0 + 1, r0) - raw(c0, r0)) * fx;
                float bottom = raw(c0, r0 + 1) + (raw(c0 + 1, r0 + 1) - raw(c0, r0 + 1)) * fx;
                out[row * n + col] = (byte) Math.round(top + (bottom - top) * fz);
            }
        }
        return out;
    }

    /** The stored byte at (col, row), wrapped or clamped like the heights. */
    private int raw(int col, int row) {
        int c = periodic ? col & (size - 1) : Math.max(0, Math.min(col, size - 1));
        int r = periodic ? row & (size - 1) : Math.max(0, Math.min(row, size - 1));
        return values[r * size + c] & 0xFF;
    }
}

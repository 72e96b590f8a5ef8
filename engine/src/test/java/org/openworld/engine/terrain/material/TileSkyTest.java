package org.openworld.engine.terrain.material;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.FloatBuffer;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.GlTest;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.ShaderLibrary;
import org.openworld.engine.gl.ShaderSources;
import org.openworld.engine.gl.Texture2D;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.HeightPyramid;
import org.openworld.engine.terrain.heights.SpectralSynthesis;
import org.openworld.engine.terrain.heights.TestTerrain;

/**
 * The tile's share of the sky seen, baked on the GPU ({@link TileSky}), against the CPU reference
 * ({@link SkyVisibility}) at every sample, on a generated tile (wrapped) and on the same heights clamped at their
 * edges, as an imported map is.
 */
@GlTest
class TileSkyTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    /**
     * The largest difference allowed at a sample, in bytes of 1/255: each side rounds V to a byte (half a step
     * each, so one step between them when the two values straddle a rounding edge), and one step more for the GPU's
     * floats against the CPU's doubles (a search distance of 3 km in a float is off by 2e-4 m, a height by a few
     * 1e-5 m, the rise by their ratio: far under a step, except where a horizon ties with the tangent plane).
     */
    static final int TOLERANCE = 2;
    /**
     * The mean difference allowed, in bytes: the rounding alone differs by 0 or 1 step, about a quarter step on
     * average for values spread evenly within a step; half a step leaves room for the ties.
     */
    static final double MEAN_TOLERANCE = 0.5;

    /**
     * Every sample of a 256² tile, wrapped and then clamped, within {@value #TOLERANCE} steps of the CPU and
     * {@value #MEAN_TOLERANCE} on average, over hollows (V &lt; 0.8) and open ground (V &gt; 0.97). With the pass
     * broken (V = 1 everywhere, a level, a distance or the wrap wrong) the hollows differ by more than 50 steps.
     */
    @Test
    void theGpuBakeIsTheCpuReference() {
        HeightMap wrapped = SpectralSynthesis.generate(TestTerrain.settings("terrain.size=256"), 3);
        compare(HeightPyramid.build(wrapped));
        compare(HeightPyramid.build(new HeightMap(wrapped.size(), wrapped.spacing(), wrapped.heights(), false)));
    }

    private static void compare(HeightPyramid pyramid) {
        HeightMap base = pyramid.base();
        ShaderLibrary shaders = new ShaderLibrary(GL.context(), ShaderSources.classpath());
        TileSky gpu;
        try (Texture2D heights = Texture2D.withMips(GL.context(), base.size(), base.size(), Format.R32F,
                Sampling.NEAREST_MIPMAP)) {
            for (int k = 0; k < pyramid.levelCount(); k++) {
                HeightMap level = pyramid.level(k);
                FloatBuffer texels = MemoryUtil.memAllocFloat(level.heights().length);
                heights.upload(k, 0, level.size(), texels.put(level.heights()).flip());
                MemoryUtil.memFree(texels);
            }
            gpu = TileSky.bake(GL.context(), shaders, heights, pyramid, 0);
        }
        SkyVisibility cpu = SkyVisibility.of(pyramid);
        assertEquals(cpu.size(), gpu.size());
        int n = gpu.size();
        int worst = 0;
        long sum = 0;
        double lowest = 1;
        double highest = 0;
        for (int row = 0; row < n; row++) {
            for (int col = 0; col < n; col++) {
                int g = (int) Math.round(255 * gpu.visibleAt(col, row));
                int error = Math.abs(g - cpu.raw(col, row));
                worst = Math.max(worst, error);
                sum += error;
                lowest = Math.min(lowest, g / 255.0);
                highest = Math.max(highest, g / 255.0);
            }
        }
        String seen = String.format(Locale.ROOT, "%s %d²: mean |ΔV| %.3f steps, worst %d, V from %.3f to %.3f",
                base.periodic() ? "wrapped" : "clamped", n, (double) sum / (n * n), worst, lowest, highest);
        System.out.println(seen);
        assertTrue(worst <= TOLERANCE, seen);
        assertTrue((double) sum / (n * n) <= MEAN_TOLERANCE, seen);
        assertTrue(lowest < 0.8, "a hollow on the tile: " + seen);
        assertTrue(highest > 0.97, "open ground on the tile: " + seen);
    }
}

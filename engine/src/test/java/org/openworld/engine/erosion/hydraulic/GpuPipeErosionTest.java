package org.openworld.engine.erosion.hydraulic;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.GlTest;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.gl.ShaderLibrary;
import org.openworld.engine.gl.ShaderSources;

/** The fragment-shader passes against the CPU reference, and the mass they keep. */
@GlTest
class GpuPipeErosionTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    private static final int N = PipeErosionTest.N;
    /** Steps compared: few enough that the two roundings have not yet parted into different channels. */
    private static final int STEPS = 10;

    private static GpuPipeErosion gpu() {
        return new GpuPipeErosion(GL.context(), new ShaderLibrary(GL.context(), ShaderSources.classpath()));
    }

    /**
     * The GPU runs the CPU's operations in the same order, so the two differ by rounding only: a GPU's division and
     * square root may be off by up to 3 ulp where Java's are exact to half of one (GLSL 4.60, 4.7.1, "Range and
     * Precision"), a multiply-add may be fused, and a value below the smallest normal float may be flushed to 0.
     * Per step each value passes through about 20 such operations, each off by up to 3 ulp of the largest value it
     * enters (the heights); the steps add their errors (the flux's scaling and the max() with 0 shrink a difference,
     * they do not grow it), so 20 · 3 ulp · steps, plus the flushed denormals. (llvmpipe agrees to the bit but for
     * those.)
     */
    private static double bound(float[] heights) {
        return 20 * 3 * Math.ulp((float) PipeErosionTest.max(heights)) * STEPS + Float.MIN_NORMAL;
    }

    private static void agree(float[] heights, PipeModel model) {
        PipeState cpu = PipeErosion.simulate(heights, N, model, STEPS);
        PipeState gpu = gpu().run(heights, N, model, STEPS);
        double worst = 0;
        double moved = 0;
        for (int i = 0; i < heights.length; i++) {
            worst = Math.max(worst, Math.abs(cpu.heights()[i] - gpu.heights()[i]));
            worst = Math.max(worst, Math.abs(cpu.sediment()[i] - gpu.sediment()[i]));
            worst = Math.max(worst, Math.abs(cpu.water()[i] - gpu.water()[i]));
            moved = Math.max(moved, Math.abs(cpu.heights()[i] - heights[i]));
        }
        double bound = bound(heights);
        assertTrue(worst < bound, model.border() + ", " + model.advection() + ": GPU and CPU differ by " + worst
                + " m, rounding allows " + bound);
        assertTrue(moved > 10 * bound, "the comparison saw erosion: " + moved + " m at most");
    }

    @Test
    void gpuFollowsTheCpuReference() {
        PipeModel model = PipeModel.tile(PipeErosionTest.SPACING, 38, PipeModel.Border.PERIODIC);
        agree(PipeErosionTest.hills(N), model);
        agree(PipeErosionTest.valley(N), model.with(PipeModel.Border.APRON));
        agree(PipeErosionTest.hills(N), model.with(PipeModel.Advection.SEMI_LAGRANGIAN));
    }

    @Test
    void gpuKeepsHeightsPlusSediment() {
        float[] h = PipeErosionTest.hills(N);
        int steps = PipeErosionTest.STEPS;
        PipeState end = gpu().run(h, N, PipeModel.tile(PipeErosionTest.SPACING, 38, PipeModel.Border.PERIODIC), steps);
        double drift = Math.abs(PipeErosionTest.sum(end.heights()) + PipeErosionTest.sum(end.sediment())
                - PipeErosionTest.sum(h));
        double bound = PipeErosionTest.roundingBound(h, steps);
        assertTrue(drift < bound, "drift " + drift + " m, rounding allows " + bound);
    }
}

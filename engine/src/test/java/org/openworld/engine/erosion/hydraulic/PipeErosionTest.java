package org.openworld.engine.erosion.hydraulic;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The CPU reference of the virtual-pipe erosion: mass kept, sediment laid in a valley's floor, slopes to the talus. */
class PipeErosionTest {

    static final int N = 32;
    /** Metres between samples, as the tile's 8 m level. */
    static final double SPACING = 8;
    /** Steps: enough for the rain to gather, run down the slopes and carry sediment a few cells. */
    static final int STEPS = 150;
    /** Roundings of b or s per cell and step: 2 by erosion, 9 by the transport, 9 by the thermal step. */
    static final int ROUNDINGS = 20;

    /** Periodic hills: a product of sines and a second, shorter wave, 10 to 70 m. */
    static float[] hills(int n) {
        float[] h = new float[n * n];
        for (int z = 0; z < n; z++) {
            for (int x = 0; x < n; x++) {
                double a = 2 * Math.PI * x / n;
                double b = 2 * Math.PI * z / n;
                h[z * n + x] = (float) (40 + 20 * Math.sin(a) * Math.cos(b) + 10 * Math.sin(2 * a + 3 * b));
            }
        }
        return h;
    }

    /** A V valley along z: sides rising 0.5 m per metre from its floor at x = n / 2, the floor falling along z. */
    static float[] valley(int n) {
        float[] h = new float[n * n];
        for (int z = 0; z < n; z++) {
            for (int x = 0; x < n; x++) {
                h[z * n + x] = (float) (0.5 * SPACING * Math.abs(x - n / 2) + 0.1 * SPACING * (n - z));
            }
        }
        return h;
    }

    static double sum(float[] a) {
        double s = 0;
        for (float v : a) {
            s += v;
        }
        return s;
    }

    static double max(float[] a) {
        double m = 0;
        for (float v : a) {
            m = Math.max(m, Math.abs(v));
        }
        return m;
    }

    /**
     * How far the total of heights and sediment may drift by rounding alone: every update of b or s rounds once, to
     * half an ulp of the largest height at most, and independent roundings add like a random walk (Higham 2002,
     * "Accuracy and Stability of Numerical Algorithms", 2.8): σ = ulp / √12 per rounding, √(count) of them; 6 σ.
     */
    static double roundingBound(float[] heights, int steps) {
        double count = (double) steps * heights.length * ROUNDINGS;
        return 6 * Math.ulp((float) max(heights)) / Math.sqrt(12) * Math.sqrt(count);
    }

    @Test
    void periodicGridKeepsHeightsPlusSediment() {
        float[] h = hills(N);
        PipeModel model = PipeModel.tile(SPACING, 38, PipeModel.Border.PERIODIC);
        PipeState end = PipeErosion.simulate(h, N, model, STEPS);
        double drift = Math.abs(sum(end.heights()) + sum(end.sediment()) - sum(h));
        double bound = roundingBound(h, STEPS);
        assertTrue(drift < bound, "drift " + drift + " m, rounding allows " + bound);
        double moved = 0;
        for (int i = 0; i < h.length; i++) {
            moved += Math.abs(end.settled()[i] - h[i]);
        }
        assertTrue(moved > 1000 * bound, "the water moved material: " + moved + " m summed over cells");
        // the paper's semi-Lagrangian step reads the load upstream instead of moving it: it drifts beyond rounding
        PipeState paper = PipeErosion.simulate(h, N, model.with(PipeModel.Advection.SEMI_LAGRANGIAN), STEPS);
        double paperDrift = Math.abs(sum(paper.heights()) + sum(paper.sediment()) - sum(h));
        assertTrue(paperDrift > bound, "semi-Lagrangian drift " + paperDrift + " m, rounding " + bound);
    }

    @Test
    void apronCountsWhatLeaves() {
        float[] h = valley(N);
        PipeErosion run = new PipeErosion(h, N, PipeModel.tile(SPACING, 38, PipeModel.Border.APRON));
        run.run(STEPS);
        PipeState end = run.state();
        double drift = Math.abs(sum(end.heights()) + sum(end.sediment()) + run.sedimentOut() - sum(h));
        double bound = roundingBound(h, STEPS);
        assertTrue(run.sedimentOut() > bound, "sediment left through the valley's mouth: " + run.sedimentOut());
        assertTrue(drift < bound, "drift " + drift + " m, rounding allows " + bound);
    }

    /** Water gathers in the floor and slows there: the sides lose material, the floor gains. */
    @Test
    void valleyFloorGetsSediment() {
        float[] h = valley(N);
        PipeState end = PipeErosion.simulate(h, N, PipeModel.tile(SPACING, 38, PipeModel.Border.APRON), STEPS);
        float[] after = end.settled();
        double floor = 0;
        double sides = 0;
        int rows = 0;
        for (int z = 4; z < N - 4; z++) { // away from the apron's edges
            rows++;
            floor += after[z * N + N / 2] - h[z * N + N / 2];
            for (int x = N / 2 - 6; x <= N / 2 - 2; x++) {
                sides += after[z * N + x] - h[z * N + x];
            }
        }
        assertTrue(floor / rows > 0, "floor changed by " + floor / rows + " m on average");
        assertTrue(sides < 0, "sides changed by " + sides + " m");
    }

    /** Without rain only the thermal step acts: a 60° ramp relaxes to the talus, 38°. */
    @Test
    void steepSlopeRelaxesToTalus() {
        int n = 16;
        double steep = Math.tan(Math.toRadians(60));
        float[] h = new float[n * n];
        for (int z = 0; z < n; z++) {
            for (int x = 0; x < n; x++) {
                h[z * n + x] = (float) (steep * SPACING * Math.min(x, 10));
            }
        }
        PipeModel dry = new PipeModel(SPACING, 0.1, 0, 0.1, 0.1, 0.3, 0.3, 0.5, 0.05, Math.tan(Math.toRadians(38)),
                PipeModel.Border.APRON, PipeModel.Advection.FLUX);
        float[] after = PipeErosion.simulate(h, n, dry, 2000).heights();
        double limit = dry.talus() * SPACING;
        double steepest = 0;
        for (int z = 0; z < n; z++) {
            for (int x = 0; x + 1 < n; x++) {
                steepest = Math.max(steepest, after[z * n + x + 1] - after[z * n + x]);
            }
        }
        // each pass halves at least an eighth of the excess left: after 2000 passes what stays is below 1 cm
        assertTrue(steepest < limit + 0.01, "steepest drop " + steepest + " m, talus " + limit + " m");
        assertTrue(Math.abs(sum(after) - sum(h)) < roundingBound(h, 2000), "volume kept");
    }
}

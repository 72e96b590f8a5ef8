package org.openworld.engine.erosion.hydraulic;

import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.HeightPyramid;

/**
 * The pipe erosion applied to a tile or to one block of an unbounded world: run on a grid of the heights, the change
 * it made (sediment laid down, positive; bed carried off, negative) handed back with the new heights, so the
 * materials can show where it lies.
 */
public final class HydraulicErosion {

    /**
     * Steps on the tile: 15 s of model time at 0.1 s. Water moves at most a cell a step, so in 150 steps the sheet
     * from a ridge reaches a valley floor a kilometre away (the tile's valleys are a few hundred metres apart) and
     * lays its load there; fewer, and the water is still on the slopes when the run stops; more, and the floors
     * fill and the deposits spread out of the valleys over the lowlands. Cost: on the tile's 512² 8 m level.
     */
    public static final int TILE_STEPS = 150;

    private HydraulicErosion() {
    }

    /**
     * What the erosion did: the heights after it, and the change on the grid it ran on.
     *
     * @param heights the new heights, of the input's size and spacing
     * @param change  the change per sample of the grid it ran on, metres: sediment laid (+) or bed carried off (−)
     */
    public record Result(HeightMap heights, HeightMap change) {
    }

    /**
     * Erodes a tile on its pyramid level {@code level} (the stream-power step's 8 m level): the run's change, read
     * bilinearly, is added to every sample of level 0, so the finer detail stays where the run did not touch it. A
     * periodic tile wraps; an imported one has an apron of its own edge.
     */
    public static Result tile(HeightMap base, int level, double talusDegrees, PipeState.Runner runner) {
        HeightMap coarse = HeightPyramid.build(base).level(level);
        PipeModel model = PipeModel.tile(coarse.spacing(), talusDegrees,
                base.periodic() ? PipeModel.Border.PERIODIC : PipeModel.Border.APRON);
        int m = coarse.size();
        float[] before = coarse.heights();
        float[] after = runner.run(before, m, model, TILE_STEPS).settled();
        float[] change = new float[m * m];
        for (int i = 0; i < change.length; i++) {
            change[i] = after[i] - before[i];
        }
        HeightMap delta = new HeightMap(m, coarse.spacing(), change, base.periodic());
        int n = base.size();
        double s = base.spacing();
        float[] in = base.heights();
        float[] out = new float[n * n];
        for (int z = 0; z < n; z++) {
            for (int x = 0; x < n; x++) {
                out[z * n + x] = (float) (in[z * n + x] + delta.heightAt((x - n / 2) * s, (z - n / 2) * s));
            }
        }
        return new Result(new HeightMap(n, s, out, base.periodic()), delta);
    }

    /**
     * Erodes one block of an unbounded world: {@code heights} holds {@code (size + 2 · apron)²} samples, the block
     * with {@code apron} samples of its surroundings on every side (from the same source, so the neighbours' aprons
     * overlap this block). Water runs off the apron's outer edge; the block inside is returned, with its change.
     * Deterministic: the same samples give the same bits, whichever block is made first. Two neighbours differ
     * where they meet by what their different borders did: each pass reads a cell's neighbours, so a border's effect
     * can reach 4 cells a step inwards, though it fades over a few cells where the water runs away from it: on
     * HydraulicBlockTest's hills (150 steps at 8 m) a block's edge is 2.2 m from the same place in a run over a far
     * larger window with an apron of 4 samples, 15 µm (float rounding) with an apron of 24. How wide an apron, and
     * whether to blend across the seam, is the caller's to choose and test on its own relief.
     */
    public static Result block(float[] heights, int size, int apron, double spacing, double talusDegrees, int steps,
                               PipeState.Runner runner) {
        int m = size + 2 * apron;
        if (heights.length != m * m) {
            throw new IllegalArgumentException(heights.length + " samples for a block of " + size + " with an apron of "
                    + apron);
        }
        PipeModel model = PipeModel.tile(spacing, talusDegrees, PipeModel.Border.APRON);
        float[] after = runner.run(heights, m, model, steps).settled();
        float[] inner = new float[size * size];
        float[] change = new float[size * size];
        for (int z = 0; z < size; z++) {
            for (int x = 0; x < size; x++) {
                int i = (z + apron) * m + x + apron;
                inner[z * size + x] = after[i];
                change[z * size + x] = after[i] - heights[i];
            }
        }
        return new Result(new HeightMap(size, spacing, inner, false), new HeightMap(size, spacing, change, false));
    }
}

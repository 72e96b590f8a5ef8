package org.openworld.engine.erosion.hydraulic;

/**
 * Where a run of the pipe erosion stopped, per cell, row-major (z rows of x).
 *
 * @param heights  terrain heights b, m
 * @param water    water depth d, m
 * @param sediment suspended sediment s, metres of material
 */
public record PipeState(float[] heights, float[] water, float[] sediment) {

    /** The heights once the water has gone: each cell's suspended sediment laid down where it is. */
    public float[] settled() {
        float[] out = new float[heights.length];
        for (int i = 0; i < out.length; i++) {
            out[i] = heights[i] + sediment[i];
        }
        return out;
    }

    /** Runs the erosion: on the GPU ({@link GpuPipeErosion}) or on the CPU ({@link PipeErosion#simulate}). */
    @FunctionalInterface
    public interface Runner {
        /**
         * @param heights {@code n × n} terrain heights, metres, row-major; not changed
         * @param steps   time steps of the model
         */
        PipeState run(float[] heights, int n, PipeModel model, int steps);
    }
}

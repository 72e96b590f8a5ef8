package org.openworld.engine.particles;

import org.openworld.engine.core.HeightField;

/**
 * The ground under the snow: a square grid of heights sampled from the world's {@link HeightField} around the eye,
 * which the update shader reads (an R32F texture) to find where a flake lands.
 *
 * <p>Heights between samples are bilinear, computed by hand from the four texels ({@code texelFetch}) rather than by
 * the texture unit, whose interpolation weights have only a few bits: so {@link #heightAt} here and
 * {@code groundAt} in {@code shaders/particles/update.vert} give the same number, and the GPU's update can be
 * checked against the CPU's. The grid's corner sits on a multiple of its spacing, so a patch sampled again further
 * on holds the same heights at the same points.
 */
public final class GroundPatch {

    private final int samples;
    private final float spacing;
    private final float originX;
    private final float originZ;
    private final float[] heights;
    private final HeightField source;

    private GroundPatch(int samples, float spacing, float originX, float originZ, float[] heights,
                        HeightField source) {
        this.samples = samples;
        this.spacing = spacing;
        this.originX = originX;
        this.originZ = originZ;
        this.heights = heights;
        this.source = source;
    }

    /**
     * Samples {@code field} on a grid of {@code samples}² points about {@code span} metres across, centred near
     * (x, z).
     */
    public static GroundPatch sample(HeightField field, double x, double z, double span, int samples) {
        if (samples < 2) {
            throw new IllegalArgumentException("a ground patch needs at least 2 samples a side, got " + samples);
        }
        float spacing = (float) (span / (samples - 1));
        float originX = (float) (Math.floor(x / spacing) * spacing - (samples - 1) / 2 * (double) spacing);
        float originZ = (float) (Math.floor(z / spacing) * spacing - (samples - 1) / 2 * (double) spacing);
        float[] heights = new float[samples * samples];
        for (int j = 0; j < samples; j++) {
            for (int i = 0; i < samples; i++) {
                heights[j * samples + i] = (float) field.heightAt(originX + i * (double) spacing,
                        originZ + j * (double) spacing);
            }
        }
        return new GroundPatch(samples, spacing, originX, originZ, heights, field);
    }

    /**
     * The ground's height at (x, z), metres: bilinear between the samples, the edge samples' beyond the grid. The
     * same float operations, in the same order, as {@code groundAt} in the update shader.
     */
    public float heightAt(float x, float z) {
        float last = samples - 1;
        float gx = Math.min(Math.max((x - originX) * (1f / spacing), 0f), last);
        float gz = Math.min(Math.max((z - originZ) * (1f / spacing), 0f), last);
        int ix = Math.min((int) Math.floor(gx), samples - 2);
        int iz = Math.min((int) Math.floor(gz), samples - 2);
        float fx = gx - ix;
        float fz = gz - iz;
        float h00 = heights[iz * samples + ix];
        float h10 = heights[iz * samples + ix + 1];
        float h01 = heights[(iz + 1) * samples + ix];
        float h11 = heights[(iz + 1) * samples + ix + 1];
        float near = h00 + (h10 - h00) * fx;
        float far = h01 + (h11 - h01) * fx;
        return near + (far - near) * fz;
    }

    /** Whether the square of half side {@code reach} around (x, z) lies on the grid, and it was sampled from {@code field}. */
    public boolean covers(HeightField field, double x, double z, double reach) {
        double end = (samples - 1) * (double) spacing;
        return field == source && x - reach >= originX && x + reach <= originX + end && z - reach >= originZ
                && z + reach <= originZ + end;
    }

    public int samples() {
        return samples;
    }

    /** Metres between neighbouring samples. */
    public float spacing() {
        return spacing;
    }

    /** World x of the first column, metres. */
    public float originX() {
        return originX;
    }

    /** World z of the first row, metres. */
    public float originZ() {
        return originZ;
    }

    /** Heights row by row (z), metres; the array itself, for the upload. */
    public float[] heights() {
        return heights;
    }
}

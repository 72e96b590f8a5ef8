package org.openworld.engine.terrain.heights;

/**
 * A square grid of heights: {@code size²} samples {@code spacing} metres apart, row-major ({@code z} rows of
 * {@code x} columns). The tile is centred on the world origin: sample (0, 0) lies at world
 * (−extent/2, −extent/2).
 *
 * <p>A generated map is <em>periodic</em> (the inverse DFT makes the last row continue into the first), so every
 * lookup wraps and copies of the tile join without a seam. An imported map is not: lookups clamp at its edges.
 */
public final class HeightMap {

    private final int size;
    private final double spacing;
    private final float[] heights;
    private final boolean periodic;
    private final float min;
    private final float max;

    /**
     * @param size     samples per side, a power of two
     * @param spacing  metres between neighbouring samples
     * @param heights  {@code size * size} heights in metres, row-major; kept, not copied
     * @param periodic whether lookups wrap (a DFT field) or clamp (an imported map)
     */
    public HeightMap(int size, double spacing, float[] heights, boolean periodic) {
        if (size < 1 || Integer.bitCount(size) != 1) {
            throw new IllegalArgumentException("height map size must be a power of two, got " + size);
        }
        if (heights.length != size * size) {
            throw new IllegalArgumentException("height map of size " + size + " needs " + size * size
                    + " samples, got " + heights.length);
        }
        if (!(spacing > 0)) {
            throw new IllegalArgumentException("sample spacing must be positive, got " + spacing);
        }
        this.size = size;
        this.spacing = spacing;
        this.heights = heights;
        this.periodic = periodic;
        float lo = Float.POSITIVE_INFINITY;
        float hi = Float.NEGATIVE_INFINITY;
        for (float h : heights) {
            lo = Math.min(lo, h);
            hi = Math.max(hi, h);
        }
        this.min = lo;
        this.max = hi;
    }

    public int size() {
        return size;
    }

    public double spacing() {
        return spacing;
    }

    /** Side of the tile, metres. */
    public double extent() {
        return size * spacing;
    }

    public boolean periodic() {
        return periodic;
    }

    /** The samples, row-major; shared, not copied. */
    public float[] heights() {
        return heights;
    }

    public float min() {
        return min;
    }

    public float max() {
        return max;
    }

    /** The sample at integer grid coordinates, wrapped (periodic) or clamped (imported). */
    public float sample(int x, int z) {
        return heights[index(z) * size + index(x)];
    }

    private int index(int i) {
        return periodic ? i & (size - 1) : Math.max(0, Math.min(size - 1, i));
    }

    /** Bilinearly interpolated height at world position (x, z), metres. */
    public double heightAt(double x, double z) {
        double gx = x / spacing + size / 2.0;
        double gz = z / spacing + size / 2.0;
        int x0 = (int) Math.floor(gx);
        int z0 = (int) Math.floor(gz);
        double fx = gx - x0;
        double fz = gz - z0;
        double top = sample(x0, z0) * (1 - fx) + sample(x0 + 1, z0) * fx;
        double bottom = sample(x0, z0 + 1) * (1 - fx) + sample(x0 + 1, z0 + 1) * fx;
        return top * (1 - fz) + bottom * fz;
    }
}

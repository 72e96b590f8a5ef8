package org.openworld.engine.terrain.heights;

import org.openworld.engine.core.HeightField;

/**
 * Where the terrain's heights come from: heights at any level of detail over any window, level L holding samples
 * {@code d_L = 2^L · d_0} metres apart, sample (i, j) at world {@code (i · d_L, j · d_L)}. The generated tile and
 * the imported map answer from their pyramid ({@link HeightPyramid}), the unbounded world sums its octave bands
 * ({@link BandedHeights}); how the levels are then cut into patches (the tile's quadtree with its copies, the
 * streamed clipmap) is the level-of-detail stage's choice, not the source's. The ground under a point, the
 * {@link HeightField} walking and the camera read, is level 0's, written once here.
 */
public interface HeightSource extends HeightField {

    /** The number of levels, level 0 the finest. */
    int levels();

    /** Metres between the samples of a level. */
    double spacing(int level);

    /** The height of a level's surface at world (x, z), metres: its samples, interpolated between them. */
    double height(int level, double x, double z);

    /** No height of any level lies below this, metres. */
    double lowest();

    /** No height of any level lies above this, metres. */
    double highest();

    /**
     * A window of a level: n × n heights, row-major, sample (i, j) at world {@code ((ix0 + i) · d, (iz0 + j) · d)}
     * for d = {@link #spacing(int)}. This default asks {@link #height} at each sample; a source with a faster way
     * to fill a window overrides it.
     */
    default float[] level(int level, long ix0, long iz0, int n) {
        double d = spacing(level);
        float[] h = new float[n * n];
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                h[j * n + i] = (float) height(level, (ix0 + i) * d, (iz0 + j) * d);
            }
        }
        return h;
    }

    /** The finest level's height at (x, z), metres. */
    @Override
    default double heightAt(double x, double z) {
        return height(0, x, z);
    }
}

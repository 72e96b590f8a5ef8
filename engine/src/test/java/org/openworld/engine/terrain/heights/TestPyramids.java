package org.openworld.engine.terrain.heights;

import java.util.ArrayList;
import java.util.List;

/** Small hand-built height pyramids for GL-free terrain tests (2 × 2 box filter, not the engine's Gaussian). */
public final class TestPyramids {

    /** Height at integer sample (x, z) of level 0, metres. */
    interface Heights {
        float at(int x, int z);
    }

    private TestPyramids() {
    }

    /** All levels from {@code size} down to one sample, each the 2 × 2 mean of the one before. */
    static HeightPyramid build(int size, double spacing, boolean periodic, Heights heights) {
        float[] base = new float[size * size];
        for (int z = 0; z < size; z++) {
            for (int x = 0; x < size; x++) {
                base[z * size + x] = heights.at(x, z);
            }
        }
        List<HeightMap> levels = new ArrayList<>();
        levels.add(new HeightMap(size, spacing, base, periodic));
        for (int n = size / 2; n >= 1; n /= 2) {
            float[] fine = levels.get(levels.size() - 1).heights();
            float[] coarse = new float[n * n];
            for (int z = 0; z < n; z++) {
                for (int x = 0; x < n; x++) {
                    int i = 2 * z * 2 * n + 2 * x;
                    coarse[z * n + x] = (fine[i] + fine[i + 1] + fine[i + 2 * n] + fine[i + 2 * n + 1]) / 4;
                }
            }
            levels.add(new HeightMap(n, spacing * size / n, coarse, periodic));
        }
        return new HeightPyramid(levels);
    }

    /** Rolling hills: a few sines, tens of metres high, periodic over the tile. */
    public static HeightPyramid hills(int size, double spacing) {
        double k = 2 * Math.PI / size;
        return build(size, spacing, true, (x, z) -> (float) (40 * Math.sin(3 * k * x) * Math.cos(2 * k * z)
                + 15 * Math.sin(7 * k * (x + z)) + 5 * Math.cos(13 * k * x)));
    }

    /** A flat plane at height 0. */
    public static HeightPyramid flat(int size, double spacing) {
        return build(size, spacing, false, (x, z) -> 0);
    }

    /** The 3 × 3 copies around the origin of a tile of the given extent, x, z pairs. */
    public static float[] threeByThree(double extent) {
        float[] offsets = new float[18];
        int c = 0;
        for (int dz = -1; dz <= 1; dz++) {
            for (int dx = -1; dx <= 1; dx++) {
                offsets[c++] = (float) (dx * extent);
                offsets[c++] = (float) (dz * extent);
            }
        }
        return offsets;
    }
}

package org.openworld.engine.terrain.lod;

import java.util.stream.IntStream;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.HeightPyramid;

/**
 * The geometric error of drawing a leaf patch's area at a coarser level: the largest |surface of level L − finest
 * height| over its level-0 samples, metres. Computed once, on the CPU, from the height pyramid.
 *
 * <p>The surface of level L is what the GPU draws: the vertices 2^L samples apart read pyramid level L exactly (the
 * same wrapping or clamping as the vertex shader), and each cell between four of them is two triangles. The patterns
 * cut cells along either diagonal (the interior along one, edge strips and the coarsest pattern along the other), so
 * a sample's error is the larger of the two triangulations'. Stitched sides read a coarser neighbour's level, whose
 * own error covers them. Cost: (levels − 1) · size² samples, a few multiplications each, in parallel over rows of
 * leaves: about 25 M samples for a 2048² map.
 */
final class GeometricError {

    private GeometricError() {
    }

    /**
     * @param levels 1 + the coarsest level asked for
     * @return [level][leaf row · leaves per side + leaf column]: metres; level 0 is all zeros
     */
    static float[][] ofLeaves(HeightPyramid pyramid, int cells, int levels) {
        int perSide = pyramid.base().size() / cells;
        float[][] errors = new float[levels][perSide * perSide];
        for (int level = 1; level < levels; level++) {
            float[] out = errors[level];
            int l = level;
            IntStream.range(0, perSide).parallel().forEach(row -> {
                for (int column = 0; column < perSide; column++) {
                    out[row * perSide + column] = leafError(pyramid, l, column * cells, row * cells, cells);
                }
            });
        }
        return errors;
    }

    /** Error of level L over the samples x0..x0 + cells, z0..z0 + cells (both borders included). */
    private static float leafError(HeightPyramid pyramid, int level, int x0, int z0, int cells) {
        HeightMap fine = pyramid.base();
        HeightMap coarse = pyramid.level(level);
        int step = 1 << level;
        float scale = 1f / step;
        float worst = 0;
        for (int z = z0; z <= z0 + cells; z++) {
            int cz = z >> level;
            float fz = (z - (cz << level)) * scale;
            for (int x = x0; x <= x0 + cells; x++) {
                int cx = x >> level;
                float fx = (x - (cx << level)) * scale;
                float nw = coarse.sample(cx, cz);
                float ne = coarse.sample(cx + 1, cz);
                float sw = coarse.sample(cx, cz + 1);
                float se = coarse.sample(cx + 1, cz + 1);
                // diagonal north-west to south-east: the triangle (nw, sw, se) below it, (nw, se, ne) above
                float a = fz >= fx ? nw + fz * (sw - nw) + fx * (se - sw) : nw + fx * (ne - nw) + fz * (se - ne);
                // diagonal north-east to south-west: the triangle (nw, ne, sw) before it, (ne, se, sw) after
                float b = fx + fz <= 1 ? nw + fx * (ne - nw) + fz * (sw - nw)
                        : se + (1 - fx) * (sw - se) + (1 - fz) * (ne - se);
                float h = fine.sample(x, z);
                worst = Math.max(worst, Math.max(Math.abs(a - h), Math.abs(b - h)));
            }
        }
        return worst;
    }
}

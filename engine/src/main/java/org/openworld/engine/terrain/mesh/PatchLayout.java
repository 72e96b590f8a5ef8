package org.openworld.engine.terrain.mesh;

import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.terrain.heights.BandedHeights;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.lod.TerrainQuadtree;

/**
 * Where the terrain programs find the heights and how the patch grid maps onto them: a tile's pyramid
 * ({@link #tile}) or the unbounded world's streamed clipmap ({@link #clipmap}, compiled with {@code TERRAIN_CLIPMAP}).
 *
 * @param mapSize    level-0 samples per side of the tile, or of one root of the unbounded world
 * @param spacing    metres between level-0 samples
 * @param cells      N, the cells per patch side
 * @param periodic   the tile wraps (generated) rather than clamps (imported); unused by the clipmap
 * @param clipSize   samples per side of each level's window, 0 for a tile
 * @param lowest     the lowest height the materials' normalised height (height01) starts from, metres
 * @param highest    the highest, where it reaches 1
 */
public record PatchLayout(int mapSize, double spacing, int cells, boolean periodic, int clipSize, float lowest,
                   float highest) {

    /** A tile's pyramid, its heights normalised from {@code lowest} to {@code highest} metres. */
    public static PatchLayout tile(HeightMap base, int cells, double lowest, double highest) {
        return new PatchLayout(base.size(), base.spacing(), cells, base.periodic(), 0, (float) lowest,
                (float) highest);
    }

    /**
     * The unbounded world: the root's samples, the clipmap's window; heights normalised as the world normalises
     * them (relief · (−sea fraction .. 1 − sea fraction), {@link BandedHeights}), so snow lines fall where a tile
     * of the same settings puts them.
     */
    public static PatchLayout clipmap(TerrainQuadtree root, int clipSize, TerrainSettings s) {
        float lowest = (float) (-s.seaFraction() * s.relief());
        return new PatchLayout(root.size(), root.extent() / root.size(), root.cells(), false, clipSize, lowest,
                (float) (lowest + s.relief()));
    }

    public boolean streamed() {
        return clipSize > 0;
    }

    /** Metres the map's texture coordinates span: the tile, or level 0's window of the clipmap. */
    public double extent() {
        return (streamed() ? clipSize : mapSize) * spacing;
    }

    /** The sampler the slopes are read through: the clipmap's slopes, or the tile's gradient map. */
    public String slopeSampler() {
        return streamed() ? "slopes" : "gradients";
    }

    /** Sets the extent the programs' texture coordinates span ({@link #extent}), under the layout's name for it. */
    public void extentUniforms(ShaderProgram p) {
        if (streamed()) {
            p.int1("clipSize").set(clipSize);
            p.float1("clipExtent").set((float) extent());
        } else {
            p.float1("extent").set((float) extent());
        }
    }

    /** Sets the vertex stage's uniforms on {@code p}: where the heights are and how the patch grid maps onto them. */
    public void apply(ShaderProgram p, int unitHeights) {
        p.use();
        p.sampler("heights", unitHeights);
        p.int1("mapSize").set(mapSize);
        p.float1("spacing").set((float) spacing);
        p.int1("cells").set(cells);
        if (streamed()) {
            p.int1("clipSize").set(clipSize);
        } else {
            p.int1("periodic").set(periodic ? 1 : 0);
        }
    }
}

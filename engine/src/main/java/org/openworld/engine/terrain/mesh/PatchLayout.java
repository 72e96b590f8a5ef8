package org.openworld.engine.terrain.mesh;

import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.terrain.heights.BandedHeights;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.lod.TerrainQuadtree;

/**
 * Where the terrain programs find the heights and how the patch grid maps onto them: a tile's pyramid
 * ({@link Tile}) or the streamed clipmap ({@link Clipmap}, compiled with {@code TERRAIN_CLIPMAP}). Each sets its own
 * uniforms, so a caller asks the same questions of both.
 */
public sealed interface PatchLayout permits PatchLayout.Tile, PatchLayout.Clipmap {

    /** Metres between level-0 samples. */
    double spacing();

    /** The lowest height the materials' normalised height (height01) starts from, metres. */
    float lowest();

    /** The highest, where it reaches 1. */
    float highest();

    /** Metres the map's texture coordinates span: the tile, or level 0's window of the clipmap. */
    double extent();

    /** The sampler the slopes are read through: the tile's gradient map, or the clipmap's slopes. */
    String slopeSampler();

    /** Sets the extent the programs' texture coordinates span ({@link #extent}), under the layout's name for it. */
    void extentUniforms(ShaderProgram p);

    /** Sets the vertex stage's uniforms on {@code p}: where the heights are and how the patch grid maps onto them. */
    void apply(ShaderProgram p, int unitHeights);

    /** A tile's pyramid, its heights normalised from {@code lowest} to {@code highest} metres. */
    static PatchLayout tile(HeightMap base, int cells, double lowest, double highest) {
        return new Tile(base.size(), base.spacing(), cells, base.periodic(), (float) lowest, (float) highest);
    }

    /**
     * The streamed clipmap: the root's samples, the clipmap's window; heights normalised as the streamed source
     * normalises them (relief · (−sea fraction .. 1 − sea fraction), {@link BandedHeights}), so snow lines fall
     * where a tile of the same settings puts them.
     */
    static PatchLayout clipmap(TerrainQuadtree root, int clipSize, TerrainSettings s) {
        float lowest = (float) (-s.seaFraction() * s.relief());
        return new Clipmap(root.size(), root.extent() / root.size(), root.cells(), clipSize, lowest,
                (float) (lowest + s.relief()));
    }

    /** The uniforms every layout sets: the heights' unit, the map's samples, their spacing and the patch grid. */
    private static void applyCommon(ShaderProgram p, int unitHeights, int mapSize, double spacing, int cells) {
        p.use();
        p.sampler("heights", unitHeights);
        p.int1("mapSize").set(mapSize);
        p.float1("spacing").set((float) spacing);
        p.int1("cells").set(cells);
    }

    /**
     * A tile's pyramid, every level of it on the GPU as the mips of one texture.
     *
     * @param mapSize  level-0 samples per side
     * @param spacing  metres between level-0 samples
     * @param cells    N, the cells per patch side
     * @param periodic the tile wraps (generated) rather than clamps (imported)
     * @param lowest   the height read as normalised 0, metres
     * @param highest  the height read as normalised 1
     */
    record Tile(int mapSize, double spacing, int cells, boolean periodic, float lowest, float highest)
            implements PatchLayout {

        @Override
        public double extent() {
            return mapSize * spacing;
        }

        @Override
        public String slopeSampler() {
            return "gradients";
        }

        @Override
        public void extentUniforms(ShaderProgram p) {
            p.float1("extent").set((float) extent());
        }

        @Override
        public void apply(ShaderProgram p, int unitHeights) {
            applyCommon(p, unitHeights, mapSize, spacing, cells);
            p.int1("periodic").set(periodic ? 1 : 0);
        }
    }

    /**
     * Streamed levels, one window of {@code clipSize²} samples a level around the camera, level L's sample i at
     * texel i mod clipSize of layer L.
     *
     * @param mapSize  level-0 samples per side of one root
     * @param spacing  metres between level-0 samples
     * @param cells    N, the cells per patch side
     * @param clipSize samples per side of each level's window
     * @param lowest   the height read as normalised 0, metres
     * @param highest  the height read as normalised 1
     */
    record Clipmap(int mapSize, double spacing, int cells, int clipSize, float lowest, float highest)
            implements PatchLayout {

        @Override
        public double extent() {
            return clipSize * spacing;
        }

        @Override
        public String slopeSampler() {
            return "slopes";
        }

        @Override
        public void extentUniforms(ShaderProgram p) {
            p.int1("clipSize").set(clipSize);
            p.float1("clipExtent").set((float) extent());
        }

        @Override
        public void apply(ShaderProgram p, int unitHeights) {
            applyCommon(p, unitHeights, mapSize, spacing, cells);
            p.int1("clipSize").set(clipSize);
        }
    }
}

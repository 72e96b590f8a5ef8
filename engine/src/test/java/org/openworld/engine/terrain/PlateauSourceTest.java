package org.openworld.engine.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.openworld.engine.terrain.heights.PlateauSource;
import org.openworld.engine.terrain.heights.StageTimes;
import org.openworld.engine.terrain.heights.TestTerrain;
import org.openworld.engine.terrain.lod.TerrainQuadtree;

/** A height source of one's own (docs/adding-a-system.md, the third walk-through) made into a tile. */
class PlateauSourceTest {

    static final int SIZE = 256;
    static final double SPACING = 8;
    static final int CELLS = 8;
    static final double TOP = 1200;
    static final double RADIUS = 500;
    static final double RIM = 300;

    final PlateauSource plateau = new PlateauSource(SPACING, 6, TOP, RADIUS, RIM);
    final TerrainData tile = TerrainData.of(plateau, SIZE, false, TestTerrain.settings("terrain.size=" + SIZE,
            "terrain.spacing=" + SPACING), 1, new StageTimes());

    @Test
    void theTileHoldsTheSourcesSamples() {
        assertEquals(TOP, plateau.heightAt(0, 0), "the ground under a point is level 0's");
        assertEquals(SIZE, tile.pyramid().base().size());
        // world sample (i, j) is texel (i + SIZE/2, j + SIZE/2): the sample at the origin is the top's, the corner
        // lies off the rim; a float holds 1200 and 0 exactly
        assertEquals(TOP, tile.pyramid().base().sample(SIZE / 2, SIZE / 2));
        assertEquals(0, tile.pyramid().base().sample(0, 0));
        float[] window = plateau.level(2, -3, 5, 4);
        assertEquals(plateau.height(2, -3 * 4 * SPACING, 5 * 4 * SPACING), window[0], 0,
                "the default window asks height() at each sample, rounded to a float the same way");
    }

    @Test
    void theFlatTopNeedsNoDetailAndTheRimDoes() {
        TerrainQuadtree tree = new TerrainQuadtree(tile.pyramid(), CELLS);
        int level = 2;
        int side = CELLS << level; // samples a side of a level-2 node: 32, 256 m
        int centre = tree.node(level, SIZE / 2 / side, SIZE / 2 / side);
        // the node [0, 256 m]² reaches 362 m from the origin, and the pyramid's 5-tap filters two levels down read
        // 3 · 2 · 16 m further: all on the top, whose heights the binomial weights (sums of 1/16) keep exact
        assertEquals(0, tree.error(centre), "a flat node is drawn coarse at no cost");
        int rim = tree.node(level, (SIZE / 2 + (int) ((RADIUS + RIM / 2) / SPACING)) / side, SIZE / 2 / side);
        // 1 m: the level-2 error must be a real loss of shape, far above the heights' float rounding
        assertTrue(tree.error(rim) > 1, "the rim's curve is lost at level 2: " + tree.error(rim) + " m");
        assertTrue(tile.snow().size() == SIZE && tile.pyramid().levelCount() == 9, "snow and pyramid follow");
    }
}

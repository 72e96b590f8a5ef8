package org.openworld.engine.terrain.lod;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.openworld.engine.core.BoundsTree;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.HeightPyramid;
import org.openworld.engine.terrain.heights.TestPyramids;

class TerrainQuadtreeTest {

    private static final int SIZE = 128;
    private static final double SPACING = 2;
    private static final int CELLS = 8;

    private final HeightPyramid pyramid = TestPyramids.hills(SIZE, SPACING);
    private final TerrainQuadtree tree = new TerrainQuadtree(pyramid, CELLS);

    @Test
    void layoutOfLevelsAndSamples() {
        assertEquals(4, tree.rootLevel(), "log2(128 / 8)");
        assertEquals(1 + 4 + 16 + 64 + 256, tree.nodeCount());
        assertEquals(4, tree.level(0));
        assertEquals(0, tree.sampleX(0));
        assertEquals(0, tree.sampleZ(0));
        for (int level = 0; level <= tree.rootLevel(); level++) {
            for (int iz = 0; iz < tree.nodesPerSide(level); iz++) {
                for (int ix = 0; ix < tree.nodesPerSide(level); ix++) {
                    int node = tree.node(level, ix, iz);
                    assertEquals(level, tree.level(node));
                    assertEquals(ix * (CELLS << level), tree.sampleX(node));
                    assertEquals(iz * (CELLS << level), tree.sampleZ(node));
                    assertEquals(ix, tree.column(node));
                    assertEquals(iz, tree.row(node));
                }
            }
        }
    }

    @Test
    void childrenAreContiguousQuadrantsInOrderNorthWestNorthEastSouthWestSouthEast() {
        BoundsTree bounds = tree.bounds();
        for (int node = 0; node < tree.nodeCount(); node++) {
            if (tree.level(node) == 0) {
                assertEquals(0, bounds.childCount(node));
                continue;
            }
            assertEquals(4, bounds.childCount(node));
            int half = CELLS << (tree.level(node) - 1);
            int[][] quadrant = {{0, 0}, {half, 0}, {0, half}, {half, half}};
            for (int q = 0; q < 4; q++) {
                int child = bounds.firstChild(node) + q;
                assertEquals(tree.level(node) - 1, tree.level(child));
                assertEquals(tree.sampleX(node) + quadrant[q][0], tree.sampleX(child));
                assertEquals(tree.sampleZ(node) + quadrant[q][1], tree.sampleZ(child));
            }
        }
    }

    /**
     * A node's box spans its samples horizontally (world x of sample i is (i − size/2) · spacing) and vertically
     * every height of pyramid levels L .. L + log2 N over the node, one sample of each level around it included;
     * a parent's box holds its children's.
     */
    @Test
    void boxesAreConservativeForEveryDrawnLevel() {
        float[] boxes = tree.bounds().boxes();
        for (int node = 0; node < tree.nodeCount(); node++) {
            int level = tree.level(node);
            int span = CELLS << level;
            int b = 6 * node;
            // float boxes (24-bit mantissa) over hundreds of metres: 1e-4 m
            assertEquals((tree.sampleX(node) - SIZE / 2.0) * SPACING, boxes[b], 1e-4);
            assertEquals((tree.sampleZ(node) - SIZE / 2.0) * SPACING, boxes[b + 2], 1e-4);
            assertEquals((tree.sampleX(node) + span - SIZE / 2.0) * SPACING, boxes[b + 3], 1e-4);
            assertEquals((tree.sampleZ(node) + span - SIZE / 2.0) * SPACING, boxes[b + 5], 1e-4);
            for (int k = level; k <= Math.min(level + tree.cellsLog2(), pyramid.levelCount() - 1); k++) {
                HeightMap map = pyramid.level(k);
                for (int z = (tree.sampleZ(node) >> k) - 1; z <= ((tree.sampleZ(node) + span) >> k) + 1; z++) {
                    for (int x = (tree.sampleX(node) >> k) - 1; x <= ((tree.sampleX(node) + span) >> k) + 1; x++) {
                        float h = map.sample(x, z);
                        assertTrue(h >= boxes[b + 1] && h <= boxes[b + 4],
                                "level " + k + " height " + h + " inside node " + node + "'s box");
                    }
                }
            }
            if (level > 0) {
                int first = tree.bounds().firstChild(node);
                for (int child = first; child < first + 4; child++) {
                    assertTrue(boxes[6 * child + 1] >= boxes[b + 1] && boxes[6 * child + 4] <= boxes[b + 4]);
                }
            }
        }
        // 50 m of the test hills' relief: a real range, not a flat box
        assertTrue(boxes[4] - boxes[1] > 50, "the hills give the root a real height range");
    }

    @Test
    void rejectsPyramidsTooShallowForTheCoarsestPatch() {
        HeightPyramid full = TestPyramids.flat(64, 1);
        HeightPyramid shallow = new HeightPyramid(List.of(full.level(0), full.level(1)));
        assertThrows(IllegalArgumentException.class, () -> new TerrainQuadtree(shallow, 8));
        assertThrows(IllegalArgumentException.class, () -> new TerrainQuadtree(full, 128));
        assertThrows(IllegalArgumentException.class, () -> new TerrainQuadtree(full, 12));
    }
}

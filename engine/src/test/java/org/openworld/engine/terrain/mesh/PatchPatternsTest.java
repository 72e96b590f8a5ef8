package org.openworld.engine.terrain.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.openworld.engine.terrain.lod.Side;

class PatchPatternsTest {

    /**
     * Interior plus four strips tile the patch exactly: every triangle counter-clockwise and non-degenerate, the
     * areas sum to N², and every edge inside the patch is used once in each direction while the unmatched edges
     * lie on the border and add up to its length. A consistently wound triangle set whose free boundary is the
     * square once around covers each point of the square exactly once.
     */
    @ParameterizedTest(name = "N = {0}")
    @ValueSource(ints = {2, 4, 32, 64})
    void interiorAndStripsTileThePatch(int cells) {
        PatchPatterns patterns = new PatchPatterns(cells);
        int max = patterns.maxStrideLog2();
        for (int a = 0; a <= max; a++) {
            for (int b = a; b <= max; b++) {
                assertTiles(patterns, a, new int[] {b, b, b, b});
                // Mixed outer strides, each side different.
                int[] mixed = new int[4];
                for (Side side : Side.values()) {
                    mixed[side.ordinal()] = a + (b - a + side.ordinal()) % (max - a + 1);
                }
                assertTiles(patterns, a, mixed);
            }
        }
    }

    private static void assertTiles(PatchPatterns patterns, int a, int[] edgeStrides) {
        int n = patterns.cells();
        String what = "a = " + a + ", edges " + java.util.Arrays.toString(edgeStrides) + ", N = " + n;
        List<Integer> pieces = new ArrayList<>();
        pieces.add(patterns.interior(a));
        for (Side side : Side.values()) {
            pieces.add(patterns.edge(side, a, edgeStrides[side.ordinal()]));
        }
        long twiceArea = 0;
        Map<Long, Integer> directed = new HashMap<>();
        int[] idx = patterns.indices();
        for (int pattern : pieces) {
            assertEquals(0, patterns.count(pattern) % 3, what);
            for (int k = patterns.first(pattern); k < patterns.first(pattern) + patterns.count(pattern); k += 3) {
                int[] t = {idx[k], idx[k + 1], idx[k + 2]};
                long up = cross(n, t[0], t[1], t[2]);
                assertTrue(up > 0, "triangle counter-clockwise seen from above and not degenerate, " + what);
                twiceArea += up;
                for (int e = 0; e < 3; e++) {
                    directed.merge(edgeKey(t[e], t[(e + 1) % 3]), 1, Integer::sum);
                }
            }
        }
        assertEquals(2L * n * n, twiceArea, "areas sum to N², " + what);
        long borderLength = 0;
        for (Map.Entry<Long, Integer> entry : directed.entrySet()) {
            assertEquals(1, entry.getValue(), "each directed edge once, " + what);
            int from = (int) (entry.getKey() >> 32);
            int to = (int) (long) entry.getKey();
            if (!directed.containsKey(edgeKey(to, from))) {
                int x0 = from % (n + 1), z0 = from / (n + 1), x1 = to % (n + 1), z1 = to / (n + 1);
                boolean onBorder = (x0 == x1 && (x0 == 0 || x0 == n)) || (z0 == z1 && (z0 == 0 || z0 == n));
                assertTrue(onBorder, "an unmatched edge lies on the patch border, " + what);
                borderLength += Math.abs(x1 - x0) + Math.abs(z1 - z0);
            }
        }
        assertEquals(4L * n, borderLength, "the free edges run once around the patch, " + what);
    }

    /** ((b − a) × (c − a)).y for grid positions (x = column, z = row). */
    private static long cross(int n, int a, int b, int c) {
        int ax = a % (n + 1), az = a / (n + 1);
        int bx = b % (n + 1) - ax, bz = b / (n + 1) - az;
        int cx = c % (n + 1) - ax, cz = c / (n + 1) - az;
        return (long) bz * cx - (long) bx * cz;
    }

    private static long edgeKey(int from, int to) {
        return ((long) from << 32) | to;
    }

    /**
     * The vertices a patch puts on a side stitched to a coarser neighbour are exactly the multiples of the outer
     * stride: those the coarse patch has there. Checked in level-0 samples against the coarse neighbour's own
     * patterns, for both schemes: quadtree nodes (own stride 1, the neighbour b levels coarser and 2^b times as
     * long) and flat grid patches (equal size, own stride 2^a, the neighbour drawn at stride 2^b).
     */
    @ParameterizedTest(name = "N = {0}")
    @ValueSource(ints = {32, 64})
    void stitchedSidesMeetTheCoarseSideVertexForVertex(int cells) {
        PatchPatterns patterns = new PatchPatterns(cells);
        int max = patterns.maxStrideLog2();
        for (Side side : Side.values()) {
            for (int coarser = 0; coarser <= max; coarser++) {
                int b = coarser;
                TreeSet<Integer> expected = new TreeSet<>();
                for (int v = 0; v <= cells; v += 1 << b) {
                    expected.add(v);
                }
                // Quadtree: fine node of level f next to a node of level f + b; sample units with f = 0.
                TreeSet<Integer> coarseInSamples = new TreeSet<>();
                sideVertices(patterns, 0, side.opposite(), 0, side.opposite()).forEach(v -> coarseInSamples.add(v << b));
                TreeSet<Integer> fineSide = sideVertices(patterns, 0, side, b, side);
                assertEquals(expected, fineSide, "quadtree " + side + " vertices at the outer stride");
                for (int part = 0; part < 1 << b; part++) {
                    int offset = part * cells;
                    TreeSet<Integer> fine = new TreeSet<>();
                    fineSide.forEach(v -> fine.add(offset + v));
                    assertEquals(coarseInSamples.subSet(offset, true, offset + cells, true), fine,
                            "quadtree " + side + ", " + b + " levels coarser, N = " + cells);
                }
                // Flat grid: every own stride a ≤ b.
                for (int a = 0; a <= b; a++) {
                    TreeSet<Integer> fine = sideVertices(patterns, a, side, b, side);
                    assertEquals(expected, fine, "flat grid " + side + " vertices at the outer stride");
                    assertEquals(sideVertices(patterns, b, side.opposite(), b, side.opposite()), fine,
                            "flat grid " + side + ", stride " + a + " next to " + b + ", N = " + cells);
                }
            }
        }
    }

    /**
     * Positions along a side (column for north and south, row for east and west) of the vertices that a whole patch
     * (interior and four strips, own stride 2^a, the stitched side at outer stride 2^b, the others at 2^a) puts on
     * the side {@code on}.
     */
    private static TreeSet<Integer> sideVertices(PatchPatterns patterns, int a, Side stitched, int b, Side on) {
        int n = patterns.cells();
        List<Integer> pieces = new ArrayList<>();
        pieces.add(patterns.interior(a));
        for (Side side : Side.values()) {
            pieces.add(patterns.edge(side, a, side == stitched ? b : a));
        }
        TreeSet<Integer> along = new TreeSet<>();
        for (int pattern : pieces) {
            for (int k = patterns.first(pattern); k < patterns.first(pattern) + patterns.count(pattern); k++) {
                int v = patterns.indices()[k];
                int x = v % (n + 1);
                int z = v / (n + 1);
                switch (on) {
                    case NORTH -> { if (z == 0) along.add(x); }
                    case SOUTH -> { if (z == n) along.add(x); }
                    case WEST -> { if (x == 0) along.add(z); }
                    case EAST -> { if (x == n) along.add(z); }
                }
            }
        }
        return along;
    }

    @ParameterizedTest(name = "N = {0}")
    @ValueSource(ints = {32, 64})
    void patternIdsAreDistinctAndIndexTheGrid(int cells) {
        PatchPatterns patterns = new PatchPatterns(cells);
        int max = patterns.maxStrideLog2();
        java.util.Set<Integer> ids = new java.util.HashSet<>();
        for (int a = 0; a <= max; a++) {
            ids.add(patterns.interior(a));
            for (int b = a; b <= max; b++) {
                for (Side side : Side.values()) {
                    ids.add(patterns.edge(side, a, b));
                }
            }
        }
        assertEquals(patterns.patternCount(), ids.size());
        int end = 0;
        for (int p = 0; p < patterns.patternCount(); p++) {
            assertEquals(end, patterns.first(p), "patterns are packed in order");
            end += patterns.count(p);
        }
        assertEquals(patterns.indices().length, end);
        for (int v : patterns.indices()) {
            assertTrue(v >= 0 && v < (cells + 1) * (cells + 1));
        }
        assertEquals(6 * (cells - 2) * (cells - 2), patterns.count(patterns.interior(0)),
                "the full-resolution interior is every cell but the outer ring, two triangles each");
        assertThrows(IllegalArgumentException.class, () -> patterns.edge(Side.NORTH, 2, 1));
        assertThrows(IllegalArgumentException.class, () -> patterns.edge(Side.NORTH, 0, max + 1));
        assertThrows(IllegalArgumentException.class, () -> new PatchPatterns(48));
    }
}

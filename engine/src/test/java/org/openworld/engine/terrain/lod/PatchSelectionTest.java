package org.openworld.engine.terrain.lod;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.lang.management.ManagementFactory;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.TreeSet;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.openworld.engine.culling.Visibility;
import org.openworld.engine.culling.Visibility.Containment;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.HeightPyramid;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.heights.TestPyramids;
import org.openworld.engine.terrain.mesh.PatchPatterns;
import org.openworld.engine.erosion.TileErosion;

class PatchSelectionTest {

    /** A tile of hills with its quadtree, drawn as the 3 × 3 copies around the origin or as one copy. */
    private static final class World {
        final TerrainQuadtree tree;
        final PatchPatterns patterns;
        final float[] offsets;
        final double extent;

        World(HeightPyramid pyramid, int cells, boolean threeByThree) {
            this.tree = new TerrainQuadtree(pyramid, cells);
            this.patterns = new PatchPatterns(cells);
            this.extent = pyramid.base().extent();
            this.offsets = threeByThree ? TestPyramids.threeByThree(extent) : new float[] {0, 0};
        }

        int copies() {
            return offsets.length / 2;
        }

        /** Lattice cell of a copy, shifted by one so that the 3 × 3 copies have cells 0..2. */
        int cellX(int copy) {
            return (int) Math.round(offsets[2 * copy] / extent) + 1;
        }

        int cellZ(int copy) {
            return (int) Math.round(offsets[2 * copy + 1] / extent) + 1;
        }

        /** A camera over the central tile, from ground level (inside the hills' boxes) to 300 m up. */
        Vector3f camera(Random random) {
            double half = extent / 2;
            return new Vector3f((float) (random.nextDouble(-half, half)), (float) random.nextDouble(-20, 300),
                    (float) (random.nextDouble(-half, half)));
        }
    }

    private static World hills(int size, double spacing, int cells, boolean threeByThree) {
        return new World(TestPyramids.hills(size, spacing), cells, threeByThree);
    }

    /** B from an eighth of a metre to 128 m, log-uniform. */
    private static double baseResolution(Random random) {
        return Math.pow(2, random.nextDouble(-3, 7));
    }

    /**
     * Either rule, half the time each: the paper's with a random B, or the screen error of a 1280 × 720 view with a
     * random field of view and a bound of a tenth of a pixel to 8 pixels.
     */
    private static DetailLimit limit(Random random) {
        if (random.nextBoolean()) {
            return DetailLimit.paper(baseResolution(random));
        }
        Matrix4f projection = new Matrix4f().perspective((float) Math.toRadians(random.nextDouble(30, 90)),
                1280f / 720, 0.5f, 40_000);
        return DetailLimit.projected(projection, 1280, 720, Math.pow(2, random.nextDouble(-3, 3)));
    }

    /**
     * The leaf cells of the copies' lattice, each holding the index of the patch covering it; fails unless the
     * patches of every copy cover its tile exactly once.
     */
    private static int[] owners(World world, PatchList patches) {
        int leaves = world.tree.nodesPerSide(0);
        int side = 3 * leaves;
        int[] owner = new int[side * side];
        java.util.Arrays.fill(owner, -1);
        for (int i = 0; i < patches.size(); i++) {
            int step = patches.sampleStep(i);
            int span = world.tree.cells() * step;
            assertEquals(span, world.tree.cells() << world.tree.level(patches.node(i)) >> (step == 1
                    ? world.tree.level(patches.node(i)) : 0), "a patch covers its node");
            int x0 = world.cellX(patches.copy(i)) * leaves + patches.originSampleX(i) / world.tree.cells();
            int z0 = world.cellZ(patches.copy(i)) * leaves + patches.originSampleZ(i) / world.tree.cells();
            for (int z = z0; z < z0 + span / world.tree.cells(); z++) {
                for (int x = x0; x < x0 + span / world.tree.cells(); x++) {
                    if (owner[z * side + x] >= 0) {
                        fail("leaf cell " + x + ", " + z + " covered twice");
                    }
                    owner[z * side + x] = i;
                }
            }
        }
        for (int c = 0; c < world.copies(); c++) {
            for (int z = 0; z < leaves; z++) {
                for (int x = 0; x < leaves; x++) {
                    int cell = (world.cellZ(c) * leaves + z) * side + world.cellX(c) * leaves + x;
                    assertTrue(owner[cell] >= 0, "copy " + c + " leaf cell " + x + ", " + z + " covered");
                }
            }
        }
        return owner;
    }

    @ParameterizedTest
    @EnumSource(LodMode.class)
    void theCutOfEveryCopyPartitionsItsTile(LodMode mode) {
        World world = hills(256, 1, 8, true);
        PatchSelection selection = new PatchSelection(world.tree);
        PatchList patches = new PatchList();
        Random random = new Random(11);
        for (int trial = 0; trial < 20; trial++) {
            selection.select(world.camera(random), world.offsets, limit(random), mode, null, patches);
            owners(world, patches);
            assertEquals(selection.cutSize(), patches.size(), "without culling the whole cut is drawn");
            assertEquals(0, selection.culledPatches());
        }
    }

    /**
     * The flat grid is a choice of its own over any residency that holds every node ({@link Residency#whole}), as the
     * terrain system hands a tile's: its cut is every leaf of every copy (the leaves a side: size / cells), where
     * the quadtree's cut under the same distance rule merges the far leaves. Over a residency that streams, the
     * quadtree stands in for it.
     */
    @Test
    void theFlatGridIsDrawnOverAWholeResidency() {
        World world = hills(256, 1, 8, true);
        int leavesPerSide = world.tree.size() / world.tree.cells();
        int everyLeaf = world.offsets.length / 2 * leavesPerSide * leavesPerSide;
        Vector3f camera = new Vector3f(0, 5, 0);
        DetailLimit limit = DetailLimit.paper(1);
        PatchList flat = new PatchList();
        PatchList cut = new PatchList();
        new PatchSelection(world.tree, Residency.ALL).select(camera, world.offsets, limit, LodMode.FLAT_GRID, null,
                flat);
        new PatchSelection(world.tree, Residency.ALL).select(camera, world.offsets, limit, LodMode.QUADTREE, null,
                cut);
        assertEquals(everyLeaf, flat.size(), "the flat grid draws every leaf of every copy");
        assertTrue(cut.size() < everyLeaf, "the quadtree merges far leaves: " + cut.size());
        Residency streaming = new Residency() {
            @Override
            public boolean drawable(int node, float x, float z) {
                return true;
            }

            @Override
            public boolean heightRange(int node, float x, float z, float[] out) {
                return false;
            }
        };
        PatchList standIn = new PatchList();
        new PatchSelection(world.tree, streaming).select(camera, world.offsets, limit, LodMode.FLAT_GRID, null,
                standIn);
        assertEquals(cut.size(), standIn.size(), "over a streaming residency the quadtree's cut stands in");
    }

    /**
     * A streamed world's node is split only when its children are resident: with the copy east of the centre
     * holding nothing finer than level 3, its cut stops there (its parents drawn instead), every copy is still
     * covered once, and the other copies are as fine as before.
     */
    @Test
    void aNodeWhoseChildrenAreNotResidentIsDrawnWhole() {
        World world = hills(256, 1, 8, true);
        float eastX = (float) world.extent;
        Residency coarseEast = new Residency() {
            @Override
            public boolean drawable(int node, float x, float z) {
                return x != eastX || z != 0 || world.tree.level(node) >= 3;
            }

            @Override
            public boolean heightRange(int node, float x, float z, float[] out) {
                return false;
            }
        };
        PatchSelection streamed = new PatchSelection(world.tree, coarseEast);
        PatchSelection whole = new PatchSelection(world.tree);
        PatchList patches = new PatchList();
        PatchList all = new PatchList();
        Vector3f camera = new Vector3f((float) (world.extent / 2 - 1), 5, 0); // at the east copy's edge
        DetailLimit limit = DetailLimit.paper(1);
        streamed.select(camera, world.offsets, limit, LodMode.QUADTREE, null, patches);
        whole.select(camera, world.offsets, limit, LodMode.QUADTREE, null, all);
        owners(world, patches);
        int finestEast = Integer.MAX_VALUE;
        int finestElsewhere = Integer.MAX_VALUE;
        for (int i = 0; i < patches.size(); i++) {
            int copy = patches.copy(i);
            boolean east = world.offsets[2 * copy] == eastX && world.offsets[2 * copy + 1] == 0;
            if (east) {
                finestEast = Math.min(finestEast, patches.level(i));
            } else {
                finestElsewhere = Math.min(finestElsewhere, patches.level(i));
            }
        }
        int finestWhole = Integer.MAX_VALUE;
        for (int i = 0; i < all.size(); i++) {
            finestWhole = Math.min(finestWhole, all.level(i));
        }
        assertEquals(0, finestWhole, "with everything resident the camera's corner is at level 0");
        assertEquals(3, finestEast, "the east copy is cut at its finest resident level");
        assertEquals(0, finestElsewhere, "the centre copy, beside the camera, still reaches level 0");
    }

    /**
     * A streamed node's known heights narrow its box for the level rule: told that every node lies 500 m below a
     * camera standing 5 m over the hills, the cut is as coarse as seen from 500 m up, far coarser than with the boxes.
     */
    @Test
    void knownHeightsNarrowTheBoxForTheLevelRule() {
        World world = hills(256, 1, 8, false);
        Residency deepBelow = knownHeights(-510, -495);
        Vector3f camera = new Vector3f(0, 5, 0);
        DetailLimit limit = DetailLimit.paper(4);
        PatchList boxes = new PatchList();
        PatchList narrowed = new PatchList();
        new PatchSelection(world.tree).select(camera, world.offsets, limit, LodMode.QUADTREE, null, boxes);
        new PatchSelection(world.tree, deepBelow).select(camera, world.offsets, limit, LodMode.QUADTREE, null,
                narrowed);
        PatchList fromAbove = new PatchList();
        new PatchSelection(world.tree).select(new Vector3f(0, 505, 0), world.offsets, limit, LodMode.QUADTREE, null,
                fromAbove);
        assertTrue(narrowed.size() < boxes.size() / 2, narrowed.size() + " patches narrowed, " + boxes.size()
                + " with the boxes");
        assertEquals(fromAbove.size(), narrowed.size(), "as seen from 500 m over the hills' boxes");
    }

    /** Every node resident, and known to lie between these heights. */
    private static Residency knownHeights(float lowest, float highest) {
        return new Residency() {
            @Override
            public boolean drawable(int node, float x, float z) {
                return true;
            }

            @Override
            public boolean heightRange(int node, float x, float z, float[] out) {
                out[0] = lowest;
                out[1] = highest;
                return true;
            }
        };
    }

    /**
     * The quadtree of a statistically uniform world: every node of a level has the level's error, every box the
     * world's height bounds, and the boxes tile the root as the pyramid's do.
     */
    @Test
    void aUniformWorldsNodesCarryTheirLevelsError() {
        float[] errors = {0, 0.5f, 1.5f, 4, 9, 20};
        TerrainQuadtree tree = TerrainQuadtree.uniform(256, 2, 8, errors, -100, 700);
        TerrainQuadtree tile = new TerrainQuadtree(TestPyramids.hills(256, 2), 8);
        assertEquals(tile.nodeCount(), tree.nodeCount());
        // doubles: an exact product, equal to round-off
        assertEquals(512, tree.extent(), 1e-9);
        float[] boxes = tree.bounds().boxes();
        float[] tileBoxes = tile.bounds().boxes();
        for (int node = 0; node < tree.nodeCount(); node++) {
            assertEquals(errors[tree.level(node)], tree.error(node), "error of node " + node);
            assertEquals(-100, boxes[6 * node + 1]);
            assertEquals(700, boxes[6 * node + 4]);
            for (int k : new int[] {0, 2, 3, 5}) {
                assertEquals(tileBoxes[6 * node + k], boxes[6 * node + k], "x/z bounds of node " + node);
            }
        }
        assertEquals(errors[2], tree.leafError(5, 2));
    }

    /**
     * No side ever borders a patch more than log2 N levels coarser, whatever B, even when the paper's rule alone
     * would ask for it (a small B next to a camera standing in the hills): then coarse nodes are split.
     */
    @Test
    void neighbourLevelsNeverDifferByMoreThanLog2N() {
        World world = hills(256, 1, 4, true);
        int limit = world.tree.cellsLog2();
        PatchSelection selection = new PatchSelection(world.tree);
        PatchList patches = new PatchList();
        Random random = new Random(5);
        int forced = 0;
        for (int trial = 0; trial < 40; trial++) {
            double base = trial % 2 == 0 ? Math.pow(2, random.nextDouble(-5, 0)) : baseResolution(random);
            selection.select(world.camera(random), world.offsets, DetailLimit.paper(base), LodMode.QUADTREE, null,
                    patches);
            forced += selection.forcedSplits();
            int[] owner = owners(world, patches);
            int side = 3 * world.tree.nodesPerSide(0);
            for (int z = 0; z < side; z++) {
                for (int x = 0; x < side; x++) {
                    int here = patches.level(owner[z * side + x]);
                    if (x + 1 < side) {
                        int east = patches.level(owner[z * side + x + 1]);
                        assertTrue(Math.abs(here - east) <= limit, "levels " + here + " and " + east + ", B = " + base);
                    }
                    if (z + 1 < side) {
                        int south = patches.level(owner[(z + 1) * side + x]);
                        assertTrue(Math.abs(here - south) <= limit, "levels " + here + " and " + south + ", B = " + base);
                    }
                }
            }
        }
        assertTrue(forced > 0, "some of these cameras need nodes split beyond the paper's rule");
    }

    /**
     * Across the whole selection, the vertices on every shared border are the same from both sides (no vertex of
     * one patch lies inside an edge of another: no T-junction), and every patch reads the same pyramid level at a
     * shared vertex, a level whose sample grid the vertex lies on: no height cracks either.
     */
    @ParameterizedTest
    @EnumSource(LodMode.class)
    void sharedBordersMatchInPositionAndSampledLevel(LodMode mode) {
        checkBorders(hills(256, 1, 8, true), mode, 3);
        checkBorders(hills(512, 2, 32, false), mode, 4);
        // and on eroded ground, whose levels' errors (and so the cut) differ from the hills'
        HeightMap eroded = TileErosion.erode(TestPyramids.hills(512, 2).base(),
                TerrainSettings.DEFAULTS.erosionTalus());
        checkBorders(new World(HeightPyramid.build(eroded), 16, true), mode, 5);
    }

    private static void checkBorders(World world, LodMode mode, long seed) {
        PatchSelection selection = new PatchSelection(world.tree);
        PatchList patches = new PatchList();
        Random random = new Random(seed);
        int size = world.tree.size();
        int n = world.tree.cells();
        for (int trial = 0; trial < 8; trial++) {
            DetailLimit rule = limit(random);
            selection.select(world.camera(random), world.offsets, rule, mode, null, patches);
            Map<Long, Integer> levelAt = new HashMap<>();
            Map<Long, Integer> patchAt = new HashMap<>();
            // Every border vertex of every patch, keyed by its level-0 sample position on the copies' lattice.
            for (int i = 0; i < patches.size(); i++) {
                for (int v : borderVertices(world.patterns, patches, i)) {
                    int column = v % (n + 1);
                    int row = v / (n + 1);
                    long gx = (long) world.cellX(patches.copy(i)) * size + patches.originSampleX(i)
                            + (long) column * patches.sampleStep(i);
                    long gz = (long) world.cellZ(patches.copy(i)) * size + patches.originSampleZ(i)
                            + (long) row * patches.sampleStep(i);
                    int level = sampledLevel(patches, i, column, row, n);
                    assertEquals(0, gx % (1L << level), "vertex on its level's samples");
                    assertEquals(0, gz % (1L << level), "vertex on its level's samples");
                    Integer before = levelAt.putIfAbsent(key(gx, gz), level);
                    if (before != null && before != level) {
                        fail("vertex " + gx + ", " + gz + " sampled at level " + before + " by patch "
                                + patchAt.get(key(gx, gz)) + " and " + level + " by patch " + i + " (" + mode
                                + ", " + rule + ")");
                    }
                    patchAt.putIfAbsent(key(gx, gz), i);
                }
            }
            // No border vertex strictly inside any border edge.
            for (int i = 0; i < patches.size(); i++) {
                for (Side side : Side.values()) {
                    TreeSet<Integer> along = new TreeSet<>();
                    for (int v : borderVertices(world.patterns, patches, i)) {
                        int column = v % (n + 1);
                        int row = v / (n + 1);
                        switch (side) {
                            case NORTH -> { if (row == 0) along.add(column); }
                            case SOUTH -> { if (row == n) along.add(column); }
                            case WEST -> { if (column == 0) along.add(row); }
                            case EAST -> { if (column == n) along.add(row); }
                        }
                    }
                    assertEquals(0, along.first());
                    assertEquals(n, along.last());
                    int step = patches.sampleStep(i);
                    long x0 = (long) world.cellX(patches.copy(i)) * size + patches.originSampleX(i);
                    long z0 = (long) world.cellZ(patches.copy(i)) * size + patches.originSampleZ(i);
                    for (int t = 0; t < n * step; t++) {
                        if (along.contains(t / step) && t % step == 0) {
                            continue;
                        }
                        long gx = switch (side) {
                            case NORTH, SOUTH -> x0 + t;
                            case EAST -> x0 + (long) n * step;
                            case WEST -> x0;
                        };
                        long gz = switch (side) {
                            case EAST, WEST -> z0 + t;
                            case SOUTH -> z0 + (long) n * step;
                            case NORTH -> z0;
                        };
                        if (levelAt.containsKey(key(gx, gz))) {
                            fail("T-junction: patch " + patchAt.get(key(gx, gz)) + " has a vertex inside a "
                                    + side + " edge of patch " + i + " (" + mode + ", " + rule + ")");
                        }
                    }
                }
            }
        }
    }

    /** Grid vertices on the border of a patch, taken from the index patterns it is drawn with. */
    private static Set<Integer> borderVertices(PatchPatterns patterns, PatchList patches, int i) {
        int n = patterns.cells();
        Set<Integer> border = new HashSet<>();
        int stride = patches.strideLog2(i);
        for (Side side : Side.values()) {
            int pattern = patterns.edge(side, stride, patches.sideStrideLog2(i, side));
            for (int k = patterns.first(pattern); k < patterns.first(pattern) + patterns.count(pattern); k++) {
                int v = patterns.indices()[k];
                int column = v % (n + 1);
                int row = v / (n + 1);
                if (column == 0 || column == n || row == 0 || row == n) {
                    border.add(v);
                }
            }
        }
        return border;
    }

    /** The pyramid level a vertex on the border of patch i samples, as the vertex shader picks it. */
    private static int sampledLevel(PatchList patches, int i, int column, int row, int n) {
        boolean west = column == 0;
        boolean east = column == n;
        boolean north = row == 0;
        boolean south = row == n;
        if ((west || east) && (north || south)) {
            Corner corner = north ? (west ? Corner.NORTH_WEST : Corner.NORTH_EAST)
                    : (west ? Corner.SOUTH_WEST : Corner.SOUTH_EAST);
            return patches.cornerLevel(i, corner);
        }
        Side side = north ? Side.NORTH : south ? Side.SOUTH : west ? Side.WEST : Side.EAST;
        return patches.sideLevel(i, side);
    }

    private static long key(long x, long z) {
        return (x << 32) | z;
    }

    /**
     * Figure 6 stays the paper's: under the paper's rule the flat grid gives every leaf, of every copy, the level
     * min(log2 N, max(0, ⌊log2(D / B)⌋)) of its box centre's distance D, computed here with logarithms, and every side
     * and corner the coarsest level of the leaves that meet there.
     */
    @Test
    void theFlatGridUnderThePaperRuleIsFigureSix() {
        World world = hills(256, 1, 8, true);
        int perSide = world.tree.nodesPerSide(0);
        float[] boxes = world.tree.bounds().boxes();
        PatchSelection selection = new PatchSelection(world.tree);
        PatchList patches = new PatchList();
        Random random = new Random(6);
        for (int trial = 0; trial < 10; trial++) {
            Vector3f camera = world.camera(random);
            double base = baseResolution(random);
            selection.select(camera, world.offsets, DetailLimit.paper(base), LodMode.FLAT_GRID, null, patches);
            assertEquals(world.copies() * perSide * perSide, patches.size(), "every leaf of every copy");
            // levels on the copies' lattice of leaves, −1 outside it
            int side = 3 * perSide;
            int[] level = new int[side * side];
            for (int c = 0; c < world.copies(); c++) {
                for (int row = 0; row < perSide; row++) {
                    for (int column = 0; column < perSide; column++) {
                        int b = 6 * world.tree.node(0, column, row);
                        double dx = (boxes[b] + boxes[b + 3]) / 2 + world.offsets[2 * c] - camera.x;
                        double dy = (boxes[b + 1] + boxes[b + 4]) / 2 - camera.y;
                        double dz = (boxes[b + 2] + boxes[b + 5]) / 2 + world.offsets[2 * c + 1] - camera.z;
                        double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
                        int l = d < 2 * base ? 0 : (int) Math.floor(Math.log(d / base) / Math.log(2));
                        level[(world.cellZ(c) * perSide + row) * side + world.cellX(c) * perSide + column] =
                                Math.min(world.tree.cellsLog2(), l);
                    }
                }
            }
            for (int i = 0; i < patches.size(); i++) {
                int x = world.cellX(patches.copy(i)) * perSide + patches.originSampleX(i) / world.tree.cells();
                int z = world.cellZ(patches.copy(i)) * perSide + patches.originSampleZ(i) / world.tree.cells();
                int own = level[z * side + x];
                assertEquals(own, patches.level(i), "leaf level, B = " + base);
                assertEquals(own, patches.strideLog2(i), "every 2^L-th vertex");
                for (Side s : Side.values()) {
                    assertEquals(Math.max(own, at(level, side, x + s.dx(), z + s.dz())), patches.sideLevel(i, s));
                }
                for (Corner k : Corner.values()) {
                    int coarsest = Math.max(Math.max(own, at(level, side, x + k.dx(), z + k.dz())),
                            Math.max(at(level, side, x + k.dx(), z), at(level, side, x, z + k.dz())));
                    assertEquals(coarsest, patches.cornerLevel(i, k), k + " corner");
                }
            }
        }
    }

    private static int at(int[] level, int side, int x, int z) {
        return x < 0 || z < 0 || x >= side || z >= side ? -1 : level[z * side + x];
    }

    /**
     * Paper equation 1: with the quadtree, R(D) ∝ 1/D², so each doubling of the world's side adds the same number
     * of patches (one more ring of distance octaves): the count grows with the logarithm of the world size. The
     * flat grid's count grows with the area, four times per doubling.
     */
    @Test
    void patchCountGrowsLogarithmicallyWithWorldSize() {
        double base = 8;
        Vector3f camera = new Vector3f(10, 2, -30);
        float[] oneCopy = {0, 0};
        int[] sizes = {256, 512, 1024, 2048};
        int[] quadtree = new int[sizes.length];
        int[] flat = new int[sizes.length];
        for (int k = 0; k < sizes.length; k++) {
            TerrainQuadtree tree = new TerrainQuadtree(TestPyramids.flat(sizes[k], 1), 32);
            PatchSelection selection = new PatchSelection(tree);
            PatchList patches = new PatchList();
            selection.select(camera, oneCopy, DetailLimit.paper(base), LodMode.QUADTREE, null, patches);
            quadtree[k] = patches.size();
            selection.select(camera, oneCopy, DetailLimit.paper(base), LodMode.FLAT_GRID, null, patches);
            flat[k] = patches.size();
        }
        String counts = java.util.Arrays.toString(quadtree);
        int firstStep = quadtree[1] - quadtree[0];
        assertTrue(firstStep > 0, "a larger world has more patches: " + counts);
        for (int k = 1; k < sizes.length; k++) {
            int step = quadtree[k] - quadtree[k - 1];
            assertTrue(Math.abs(step - firstStep) <= firstStep / 4, "the same increment per doubling: " + counts);
            assertEquals(4 * flat[k - 1], flat[k], "the flat grid pays the area");
        }
        // a quadtree's patch count grows with the log of the world's extent, not its area: 64× the area adds about 3
        // levels of patches, far under 4×
        assertTrue(quadtree[3] < 4 * quadtree[0], "64 times the area, under 4 times the patches: " + counts);
    }

    /**
     * Patches whose node (or an ancestor) the culling placed outside the frustum are not drawn; the rest are, with
     * the levels they have without culling (neighbour levels come from the whole cut), and drawn + culled = cut.
     */
    @ParameterizedTest
    @EnumSource(LodMode.class)
    void patchesOutsideTheFrustumAreLeftOut(LodMode mode) {
        World world = hills(256, 1, 8, true);
        int nodes = world.tree.nodeCount();
        PatchSelection selection = new PatchSelection(world.tree);
        PatchList all = new PatchList();
        PatchList drawn = new PatchList();
        Random random = new Random(23);
        Containment[] values = Containment.values();
        int outside = 0;
        for (int trial = 0; trial < 10; trial++) {
            Vector3f camera = world.camera(random);
            DetailLimit rule = limit(random);
            Visibility visibility = new Visibility(world.copies(), nodes);
            Containment[] resolved = new Containment[world.copies() * nodes];
            for (int c = 0; c < world.copies(); c++) {
                for (int node = 0; node < nodes; node++) {
                    Containment own = node == 0 ? Containment.PARTIAL : values[random.nextInt(3)];
                    visibility.set(c, node, own);
                    resolved[c * nodes + node] = own;
                }
                // Top-down: a node under an OUTSIDE or INSIDE parent shares its answer.
                for (int node = 0; node < nodes; node++) {
                    if (world.tree.level(node) > 0 && resolved[c * nodes + node] != Containment.PARTIAL) {
                        int first = world.tree.bounds().firstChild(node);
                        for (int child = first; child < first + 4; child++) {
                            resolved[c * nodes + child] = resolved[c * nodes + node];
                        }
                    }
                }
            }
            selection.select(camera, world.offsets, rule, mode, null, all);
            int cut = selection.cutSize();
            selection.select(camera, world.offsets, rule, mode, visibility, drawn);
            assertEquals(cut, selection.cutSize(), "culling does not change the cut");
            assertEquals(drawn.size(), selection.visiblePatches());
            assertEquals(cut, drawn.size() + selection.culledPatches());

            Map<Long, String> expected = new HashMap<>();
            for (int i = 0; i < all.size(); i++) {
                if (resolved[all.copy(i) * nodes + all.node(i)] != Containment.OUTSIDE) {
                    expected.put((long) all.copy(i) * nodes + all.node(i), describe(all, i));
                }
            }
            Map<Long, String> actual = new HashMap<>();
            for (int i = 0; i < drawn.size(); i++) {
                actual.put((long) drawn.copy(i) * nodes + drawn.node(i), describe(drawn, i));
            }
            outside += all.size() - expected.size();
            assertEquals(expected, actual);
        }
        assertTrue(outside > 0, "some patches were outside");
    }

    private static String describe(PatchList patches, int i) {
        StringBuilder s = new StringBuilder();
        s.append(patches.originSampleX(i)).append(',').append(patches.originSampleZ(i)).append(" step ")
                .append(patches.sampleStep(i)).append(" level ").append(patches.level(i)).append('/')
                .append(patches.strideLog2(i));
        for (Side side : Side.values()) {
            s.append(' ').append(side).append(patches.sideLevel(i, side)).append('/')
                    .append(patches.sideStrideLog2(i, side));
        }
        for (Corner corner : Corner.values()) {
            s.append(' ').append(corner).append(patches.cornerLevel(i, corner));
        }
        return s.toString();
    }

    /** Once its arrays have grown, a selection allocates nothing: it runs every frame. */
    @Test
    void selectionAllocatesNothingOnceWarm() {
        World world = hills(512, 2, 32, true);
        PatchSelection selection = new PatchSelection(world.tree);
        PatchList patches = new PatchList();
        Visibility visibility = new Visibility(world.copies(), world.tree.nodeCount());
        for (int c = 0; c < world.copies(); c++) {
            visibility.set(c, 0, Containment.PARTIAL);
            for (int node = 1; node < world.tree.nodeCount(); node++) {
                visibility.set(c, node, node % 3 == 0 ? Containment.OUTSIDE : Containment.PARTIAL);
            }
        }
        Vector3f camera = new Vector3f(100, 40, -200);
        DetailLimit paper = DetailLimit.paper(8);
        DetailLimit screen = DetailLimit.projected(new Matrix4f().perspective(1, 16f / 9, 0.5f, 40_000), 1280, 720, 1);
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        for (LodMode mode : LodMode.values()) {
            for (DetailLimit limit : new DetailLimit[] {paper, screen}) {
                for (int warm = 0; warm < 3; warm++) {
                    selection.select(camera, world.offsets, limit, mode, visibility, patches);
                }
                long before = threads.getCurrentThreadAllocatedBytes();
                for (int frame = 0; frame < 10; frame++) {
                    camera.x += 3;
                    selection.select(camera, world.offsets, limit, mode, visibility, patches);
                }
                long allocated = threads.getCurrentThreadAllocatedBytes() - before;
                assertEquals(0, allocated, mode + " " + limit + " allocated " + allocated + " bytes in 10 frames");
            }
        }
    }
}

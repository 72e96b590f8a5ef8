package org.openworld.engine.terrain.lod;

import org.openworld.engine.core.BoundsTree;
import org.openworld.engine.terrain.heights.BandedHeights;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.HeightPyramid;

/**
 * The quadtree of terrain patches over one tile of a {@link HeightPyramid}. A leaf covers N × N height samples; a
 * node of level L covers 2^L × 2^L leaves and is drawn with the same N-cell vertex grid, its vertices 2^L samples
 * apart, sampling pyramid level L. The root, level log2(size / N), is the whole tile.
 *
 * <p>Nodes are numbered breadth first, and within a depth in Morton (Z) order of their position, so the children of
 * a node are contiguous and the node at any depth above a given one is found by shifting its Morton code, without
 * walking the tree: {@link #node(int, int, int)}. The children of a node are in the order north-west, north-east,
 * south-west, south-east.
 *
 * <p>The {@linkplain #bounds() boxes} are conservative for everything the node can draw: its own level L inside and,
 * on a side stitched to a coarser neighbour, up to level L + log2 N, so a node's height range spans pyramid levels
 * L .. L + log2 N (those that exist) over the node, widened by one sample of each level on every side; a parent's
 * box is the union of its children's and its own coarsest level's.
 *
 * <p>Each node also knows its {@linkplain #error geometric error}: how far, in metres, the surface of its level lies
 * from the finest heights anywhere over its area ({@link GeometricError}), what the screen-error rule projects.
 */
public final class TerrainQuadtree {

    private final int size;
    private final double spacing;
    private final int cells;
    private final int cellsLog2;
    private final int rootLevel;
    private final int[] level;
    private final int[] sampleX;
    private final int[] sampleZ;
    private final int[] firstChild;
    private final BoundsTree bounds;
    /** Per level 0 .. max(root level, log2 N), per leaf (row-major): the leaf's error at that level, metres. */
    private final float[][] leafError;
    private final float[] error;

    /**
     * The quadtree over a tile of heights: boxes and errors measured on the pyramid, node by node.
     *
     * @param pyramid the heights; needs levels 0 .. max(root level, log2 N), the coarsest levels any patch samples
     * @param cells   N, the cells per patch side: a power of two, at most the map size
     */
    public TerrainQuadtree(HeightPyramid pyramid, int cells) {
        this(pyramid.base().size(), pyramid.base().spacing(), cells);
        int needed = Math.max(rootLevel, cellsLog2) + 1;
        if (pyramid.levelCount() < needed) {
            throw new IllegalArgumentException("a " + size + "² map with " + cells + "-cell patches needs "
                    + needed + " pyramid levels, got " + pyramid.levelCount());
        }
        float[][] errors = GeometricError.ofLeaves(pyramid, cells, needed);
        System.arraycopy(errors, 0, leafError, 0, needed);
        float[] boxes = bounds.boxes();
        float[] range = new float[2];
        int coarsest = pyramid.levelCount() - 1;
        // Deepest first, so a parent can take the union of its children's finished boxes.
        for (int node = level.length - 1; node >= 0; node--) {
            int lvl = level[node];
            int span = cells << lvl;
            range[0] = Float.POSITIVE_INFINITY;
            range[1] = Float.NEGATIVE_INFINITY;
            if (lvl == 0) {
                for (int k = 0; k <= Math.min(cellsLog2, coarsest); k++) {
                    widenByLevel(pyramid, range, k, sampleX[node], sampleZ[node], span);
                }
            } else {
                for (int c = firstChild[node]; c < firstChild[node] + 4; c++) {
                    range[0] = Math.min(range[0], boxes[6 * c + 1]);
                    range[1] = Math.max(range[1], boxes[6 * c + 4]);
                }
                // The children cover levels lvl − 1 .. lvl − 1 + log2 N; the parent also draws lvl + log2 N.
                if (lvl + cellsLog2 <= coarsest) {
                    widenByLevel(pyramid, range, lvl + cellsLog2, sampleX[node], sampleZ[node], span);
                }
            }
            boxes[6 * node + 1] = range[0];
            boxes[6 * node + 4] = range[1];
        }
        measureNodeErrors();
    }

    /**
     * The quadtree over one root of a statistically uniform world (the unbounded world's, {@link BandedHeights}),
     * whose heights are not all known when it is made: every node of a level gets that level's error, every box the
     * world's height bounds.
     *
     * @param size       level-0 samples per root side: N · 2^root level
     * @param spacing    metres between level-0 samples
     * @param cells      N, the cells per patch side
     * @param levelError per level 0 .. max(root level, log2 N): how far that level's surface lies from the finest
     *                   heights, metres (0 for level 0)
     * @param lowest     no height of any level lies below this, metres
     * @param highest    nor above this
     */
    public static TerrainQuadtree uniform(int size, double spacing, int cells, float[] levelError, float lowest,
                                   float highest) {
        TerrainQuadtree tree = new TerrainQuadtree(size, spacing, cells);
        if (levelError.length < tree.leafError.length) {
            throw new IllegalArgumentException("errors for " + levelError.length + " levels, need "
                    + tree.leafError.length);
        }
        for (int l = 0; l < tree.leafError.length; l++) {
            java.util.Arrays.fill(tree.leafError[l], levelError[l]);
        }
        float[] boxes = tree.bounds.boxes();
        for (int node = 0; node < tree.level.length; node++) {
            boxes[6 * node + 1] = lowest;
            boxes[6 * node + 4] = highest;
        }
        tree.measureNodeErrors();
        return tree;
    }

    /** The nodes, their horizontal boxes and room for the leaves' errors; heights and errors are filled in after. */
    private TerrainQuadtree(int size, double spacing, int cells) {
        if (cells < 2 || Integer.bitCount(cells) != 1 || cells > size) {
            throw new IllegalArgumentException("cells per patch side must be a power of two in 2.." + size
                    + ", got " + cells);
        }
        this.size = size;
        this.spacing = spacing;
        this.cells = cells;
        this.cellsLog2 = Integer.numberOfTrailingZeros(cells);
        this.rootLevel = Integer.numberOfTrailingZeros(size / cells);
        int nodes = depthOffset(rootLevel + 1);
        this.level = new int[nodes];
        this.sampleX = new int[nodes];
        this.sampleZ = new int[nodes];
        this.firstChild = new int[nodes];
        int[] childCount = new int[nodes];
        for (int depth = 0; depth <= rootLevel; depth++) {
            int lvl = rootLevel - depth;
            int perSide = 1 << depth;
            for (int m = 0; m < perSide * perSide; m++) {
                int node = depthOffset(depth) + m;
                level[node] = lvl;
                sampleX[node] = deinterleave(m) * (cells << lvl);
                sampleZ[node] = deinterleave(m >>> 1) * (cells << lvl);
                if (lvl > 0) {
                    firstChild[node] = depthOffset(depth + 1) + 4 * m;
                    childCount[node] = 4;
                }
            }
        }
        this.bounds = new BoundsTree(horizontalBoxes(), firstChild, childCount);
        int leaves = 1 << rootLevel;
        this.leafError = new float[Math.max(rootLevel, cellsLog2) + 1][leaves * leaves];
        this.error = new float[nodes];
    }

    /** Each node's error: the worst of its leaves' errors at the node's level. */
    private void measureNodeErrors() {
        int leaves = nodesPerSide(0);
        for (int node = 0; node < level.length; node++) {
            int span = 1 << level[node];
            int column = sampleX[node] / cells;
            int row = sampleZ[node] / cells;
            float worst = 0;
            for (int z = row; z < row + span; z++) {
                for (int x = column; x < column + span; x++) {
                    worst = Math.max(worst, leafError[level[node]][z * leaves + x]);
                }
            }
            error[node] = worst;
        }
    }

    /** Side of the tile (or root), metres. */
    public double extent() {
        return size * spacing;
    }

    /** N, the cells per patch side. */
    public int cells() {
        return cells;
    }

    /** log2 N: the largest level difference between neighbouring patches that the stitching handles. */
    public int cellsLog2() {
        return cellsLog2;
    }

    /** Level of the root node: log2(size / N). */
    public int rootLevel() {
        return rootLevel;
    }

    public int nodeCount() {
        return level.length;
    }

    /**
     * The node's geometric error: the largest |surface of its level − finest height| over its level-0 samples,
     * borders included, metres; 0 for a leaf.
     */
    public float error(int node) {
        return error[node];
    }

    /**
     * The error of a leaf drawn at a level, as the flat grid draws it (every 2^level-th vertex), metres.
     *
     * @param level 0 .. max(root level, log2 N)
     */
    public float leafError(int leaf, int level) {
        return leafError[level][row(leaf) * nodesPerSide(0) + column(leaf)];
    }

    /** Height samples per tile (or root) side at level 0. */
    public int size() {
        return size;
    }

    /** Level of a node: 0 for a leaf; the pyramid level its interior samples. */
    public int level(int node) {
        return level[node];
    }

    /** Level-0 sample index (column) of the node's north-west corner within the tile. */
    public int sampleX(int node) {
        return sampleX[node];
    }

    /** Level-0 sample index (row) of the node's north-west corner within the tile. */
    public int sampleZ(int node) {
        return sampleZ[node];
    }

    /** Nodes of a level per tile side: 2^(root level − level). */
    public int nodesPerSide(int level) {
        return 1 << (rootLevel - level);
    }

    /** The node of a level at position (ix, iz) in that level's grid of nodes, 0 ≤ ix, iz < nodesPerSide(level). */
    public int node(int level, int ix, int iz) {
        return depthOffset(rootLevel - level) + interleave(ix, iz);
    }

    /** Column of a node in its level's grid of nodes. */
    public int column(int node) {
        return sampleX[node] >> (cellsLog2 + level[node]);
    }

    /** Row of a node in its level's grid of nodes. */
    public int row(int node) {
        return sampleZ[node] >> (cellsLog2 + level[node]);
    }

    /**
     * World-space boxes of the tile centred on the origin (the copy at offset 0): world x of sample i is
     * (i − size/2) · spacing. Node 0 is the root; the children of a node are contiguous.
     */
    public BoundsTree bounds() {
        return bounds;
    }

    /** Index of the first node at a depth (root depth 0): (4^depth − 1) / 3. */
    static int depthOffset(int depth) {
        return ((1 << (2 * depth)) - 1) / 3;
    }

    /** Morton code: the bits of x at even positions, those of z at odd ones. */
    static int interleave(int x, int z) {
        return spread(x) | (spread(z) << 1);
    }

    private static int spread(int v) {
        v &= 0xFFFF;
        v = (v | (v << 8)) & 0x00FF00FF;
        v = (v | (v << 4)) & 0x0F0F0F0F;
        v = (v | (v << 2)) & 0x33333333;
        return (v | (v << 1)) & 0x55555555;
    }

    /** The even bits of a Morton code, packed. */
    private static int deinterleave(int m) {
        m &= 0x55555555;
        m = (m | (m >>> 1)) & 0x33333333;
        m = (m | (m >>> 2)) & 0x0F0F0F0F;
        m = (m | (m >>> 4)) & 0x00FF00FF;
        return (m | (m >>> 8)) & 0x0000FFFF;
    }

    /** Every node's box with its x and z spans set (world metres, the tile centred on the origin), heights 0. */
    private float[] horizontalBoxes() {
        double half = size / 2.0;
        float[] boxes = new float[6 * level.length];
        for (int node = 0; node < level.length; node++) {
            int span = cells << level[node];
            boxes[6 * node] = (float) ((sampleX[node] - half) * spacing);
            boxes[6 * node + 2] = (float) ((sampleZ[node] - half) * spacing);
            boxes[6 * node + 3] = (float) ((sampleX[node] + span - half) * spacing);
            boxes[6 * node + 5] = (float) ((sampleZ[node] + span - half) * spacing);
        }
        return boxes;
    }

    /**
     * Widens {min, max} by the heights of pyramid level k over level-0 samples x0 .. x0 + span (and z likewise),
     * plus one level-k sample each side.
     */
    private static void widenByLevel(HeightPyramid pyramid, float[] range, int k, int x0, int z0, int span) {
        HeightMap map = pyramid.level(k);
        for (int z = (z0 >> k) - 1; z <= ((z0 + span) >> k) + 1; z++) {
            for (int x = (x0 >> k) - 1; x <= ((x0 + span) >> k) + 1; x++) {
                float h = map.sample(x, z);
                range[0] = Math.min(range[0], h);
                range[1] = Math.max(range[1], h);
            }
        }
    }
}

package org.openworld.engine.terrain.lod;

import org.joml.Vector3fc;
import org.openworld.engine.core.BoundsTree;
import org.openworld.engine.culling.Visibility;
import org.openworld.engine.culling.Visibility.Containment;

/**
 * The paper's geomipmapping as written (2.5, figure 6): the tile is a fixed grid of equal patches (the quadtree's
 * leaves, so the culling results apply as they are), and each visible patch gets its own level. By the paper's rule
 * that is L = clamp(⌊log2(D / B)⌋, 0, log2 N) from the distance D between the camera and the patch's centroid (taken
 * as the centre of its bounding box); by the screen-error rule the coarsest L ≤ log2 N whose error
 * ({@link TerrainQuadtree#leafError}) the {@link DetailLimit} accepts from the distance to the patch's box. A
 * level-L patch draws every 2^L-th vertex of its N-cell grid and samples pyramid level L; a side next to a coarser
 * patch draws that patch's vertex stride and samples its level, a corner the coarsest of the four patches touching
 * it. Levels never differ by more than log2 N, which the patterns stitch.
 *
 * <p>Every patch of every copy is in the cut, so the cost grows with the world's area; it is kept to reproduce the
 * paper, {@link QuadtreeLod} is the scalable scheme. Culled subtrees are skipped; neighbour levels are computed
 * directly from the neighbours' distances, visible or not, so no per-patch state is kept.
 */
final class FlatGridLod implements LodScheme {

    private static final Side[] SIDES = Side.values();
    private static final Corner[] CORNERS = Corner.values();

    private final TerrainQuadtree tree;
    private final BoundsTree bounds;
    private final CopyLattice lattice = new CopyLattice();
    private final int[] sideLevel = new int[4];
    private Vector3fc camera;
    private DetailLimit limit;
    private Visibility visibility;

    private int cut;
    private int culled;
    private int visited;

    FlatGridLod(TerrainQuadtree tree) {
        this.tree = tree;
        this.bounds = tree.bounds();
    }

    @Override
    public void select(Vector3fc camera, float[] offsets, DetailLimit limit, Visibility visibility, PatchList out) {
        lattice.update(offsets, tree.extent());
        this.camera = camera;
        this.limit = limit;
        this.visibility = visibility;
        int leaves = tree.nodesPerSide(0) * tree.nodesPerSide(0);
        cut = lattice.copies() * leaves;
        culled = 0;
        visited = 0;
        out.clear();
        for (int copy = 0; copy < lattice.copies(); copy++) {
            descend(copy, 0, visibility == null ? null : visibility.root(copy), out);
        }
        this.camera = null;
        this.limit = null;
        this.visibility = null;
    }

    @Override
    public int cutSize() {
        return cut;
    }

    @Override
    public int culledPatches() {
        return culled;
    }

    @Override
    public int visitedNodes() {
        return visited;
    }

    @Override
    public int forcedSplits() {
        return 0;
    }

    private void descend(int copy, int node, Containment containment, PatchList out) {
        visited++;
        int level = tree.level(node);
        if (containment == Containment.OUTSIDE) {
            culled += 1 << (2 * level);
        } else if (level == 0) {
            emit(copy, node, out);
        } else {
            int first = bounds.firstChild(node);
            for (int child = first; child < first + 4; child++) {
                descend(copy, child, containment == null ? null : visibility.of(copy, child, containment), out);
            }
        }
    }

    private void emit(int copy, int leaf, PatchList out) {
        int column = tree.column(leaf);
        int row = tree.row(leaf);
        int level = leafLevel(copy, column, row);
        int i = out.add(leaf, copy, tree.sampleX(leaf), tree.sampleZ(leaf), 1, level, level);
        for (Side side : SIDES) {
            int shared = Math.max(level, leafLevel(copy, column + side.dx(), row + side.dz()));
            sideLevel[side.ordinal()] = shared;
            out.setSide(i, side, shared, shared);
        }
        for (Corner corner : CORNERS) {
            int coarsest = Math.max(sideLevel[corner.northSouth().ordinal()], sideLevel[corner.eastWest().ordinal()]);
            out.setCorner(i, corner, Math.max(coarsest, leafLevel(copy, column + corner.dx(), row + corner.dz())));
        }
    }

    /**
     * Level of the leaf at (column, row) of a copy's leaf grid, one step outside reaching into the adjacent copy;
     * −1 where no copy lies.
     */
    private int leafLevel(int copy, int column, int row) {
        int perSide = tree.nodesPerSide(0);
        int dx = column < 0 ? -1 : column >= perSide ? 1 : 0;
        int dz = row < 0 ? -1 : row >= perSide ? 1 : 0;
        int c = dx == 0 && dz == 0 ? copy : lattice.neighbour(copy, dx, dz);
        if (c < 0) {
            return -1;
        }
        int leaf = tree.node(0, column - dx * perSide, row - dz * perSide);
        if (limit instanceof DetailLimit.Paper paper) {
            return Math.min(tree.cellsLog2(), LodRule.level(centroidDistance(c, leaf), paper.baseResolution()));
        }
        double distance = boxDistance(c, leaf);
        for (int level = tree.cellsLog2(); level > 0; level--) {
            if (limit.fineEnough(level, tree.leafError(leaf, level), distance)) {
                return level;
            }
        }
        return 0;
    }

    /** The paper's D: from the camera to the centre of the leaf's box in a copy, metres. */
    private double centroidDistance(int copy, int leaf) {
        float[] boxes = bounds.boxes();
        int b = 6 * leaf;
        double x = (boxes[b] + boxes[b + 3]) * 0.5 + lattice.offsetX(copy) - camera.x();
        double y = (boxes[b + 1] + boxes[b + 4]) * 0.5 - camera.y();
        double z = (boxes[b + 2] + boxes[b + 5]) * 0.5 + lattice.offsetZ(copy) - camera.z();
        return Math.sqrt(x * x + y * y + z * z);
    }

    /** From the camera to the nearest point of the leaf's box in a copy, metres: the bound the error rule needs. */
    private double boxDistance(int copy, int leaf) {
        return bounds.distance(leaf, lattice.offsetX(copy), lattice.offsetZ(copy), camera);
    }
}

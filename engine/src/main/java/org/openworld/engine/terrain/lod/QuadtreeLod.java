package org.openworld.engine.terrain.lod;

import java.util.Arrays;

import org.joml.Vector3fc;
import org.openworld.engine.core.BoundsTree;
import org.openworld.engine.culling.Visibility;
import org.openworld.engine.culling.Visibility.Containment;

/**
 * A {@link TerrainQuadtree} cut: starting at the root, a node is split while the {@link DetailLimit} finds it not
 * fine enough and its children's heights are {@linkplain Residency resident}; the nodes not split form the cut, a
 * partition of the tile into patches whose size grows with distance. With the paper's rule (L_B(D) = ⌊log2(D / B)⌋, {@link LodRule#level}) a node of level L is split while
 * D < B · 2^L, and over a world of side S the cut holds a constant number of patches per distance octave, so it grows
 * like log S: equation 1 with R(D) ∝ 1/D². With the screen-error rule a node is split while its geometric error
 * ({@link TerrainQuadtree#error}) covers more than the allowed pixels from D: flat ground stays coarse near the eye,
 * a ridge stays fine far away.
 *
 * <p>D is the distance from the camera to the nearest point of the node's 3D bounding box, not to its centroid as in
 * the paper's flat grid. A big node's centroid can be far from the camera while the camera stands on the node itself:
 * by centroid distance the root of a large world would be drawn at its coarsest level under the camera's feet. The box
 * distance is zero for a node that contains the camera, so every node around the camera is split down to full
 * resolution, and a node's level is never coarser than the rule asks for at any of its points.
 *
 * <p>Stitching. A side can zip to a neighbour at most log2 N levels coarser ({@link org.openworld.engine.terrain.mesh.PatchPatterns}). The paper's rule
 * keeps neighbour differences small when B is large against a leaf patch, but with a tiny B a coarse node can border
 * a much finer one, and the screen-error rule puts a rough node next to a flat one; the cut is then repaired by
 * splitting the coarse node ({@link #forcedSplits()}) until no side sees a difference above log2 N. Then each patch
 * looks up its neighbour across each side and the one across each corner: a side samples the coarser level of the
 * two patches sharing it, a corner the coarsest of the up to four patches touching it, so both patches of a shared
 * vertex fetch the very same height.
 *
 * <p>Geomorphing (CDLOD-style, Strugar 2009). Each drawn node gets a morph factor k from its level distance D (its
 * box distance, or its parent's when larger, so that D never shrinks down the tree): k rises from 0 to 1 over the
 * last {@link #MORPH_SHARE} of the distances from M(node) to M(parent), M = {@link DetailLimit#fineFrom} (paper rule
 * B · 2^L; screen error e · f / p), and the vertex shader moves each vertex's height by k from its own level's towards the
 * parent's surface: an even vertex (a parent vertex) to the parent level's height, an odd one to the mean of the
 * parent-level heights of its two even neighbours along its odd axis, or along the cell's diagonal when odd in both
 * (the diagonal {@link org.openworld.engine.terrain.mesh.PatchPatterns} cuts every cell with), its x and z unchanged. Why nothing jumps: a node is
 * split exactly when D &lt; M(node), where its own k is 0 and it shows its own surface, and its children appear with
 * D ≥ the node's D ≥ M(node) = their M(parent), so with k = 1: on that same surface; they merge back at the same
 * point, in reverse. Between, k follows the camera's motion continuously. The factor is the node's, not each vertex's
 * (as CDLOD's is): a vertex's own distance can exceed its node's box distance by the box's diagonal, and with the
 * vertex's distance the band would have to begin a diagonal beyond M(node), which left it empty wherever the diagonal
 * exceeds M(parent) − M(node) (low levels, tall boxes: every level of a streamed world's 2.4 km boxes), and the level
 * then stepped by up to the pixel bound.
 *
 * <p>Shared vertices must agree, so k on an edge is not the patch's own. A side vertex samples the side's level
 * (the coarser patch's); its k is that of the neighbour that samples that level (the coarser neighbour), and when
 * both patches have the same level, the larger of the two: both compute max(k_A, k_B), which is 1 when either
 * merges (so the side is the parent's edge, which the remaining neighbour then reads unmorphed at the parent's k = 0)
 * and equals the remaining patch's when the other has just split (the new children have k = 1). A corner takes the
 * largest k over the patches touching it that sample its level: the patch itself, its two side neighbours (each side
 * carries its neighbour's k only when that neighbour samples the side's level) and the diagonal one. An edge vertex
 * on a coarser neighbour's level thus morphs with that neighbour, not by itself. Limits: the reflection's cut is chosen
 * from the mirrored eye, and its k from that eye's distances; a node split only to keep neighbours within log2 N levels
 * ({@link #forcedSplits()}) shows its parent's unmorphed surface; the edge strips' fans are not the parent's
 * triangles, so inside a patch's outermost ring of cells k = 1 matches the parent at the vertices only.
 *
 * <p>Cost. The cut is found top-down, touching only the nodes above it. Selected nodes are marked with a per-frame
 * stamp; a neighbour lookup walks from the root towards the same-level node across the side (the node above a
 * given one at any depth is its Morton code shifted, {@link TerrainQuadtree#node}) and stops at the first stamped
 * node: a coarser or equal neighbour, or none above that level, meaning the neighbours there are finer. Nothing is
 * allocated once the arrays have grown to the cut's size.
 */
public final class QuadtreeLod implements LodScheme {

    private static final Side[] SIDES = Side.values();
    private static final Corner[] CORNERS = Corner.values();
    /**
     * The share of the level distances from M(node) to M(parent) over which a node morphs, the last ones: the rest
     * shows the node's own surface, finer than the rule asks. Measured with 0.3, 0.5 and 1 (the README shot at
     * 960 × 540 against no morphing: mean ΔE00 0.41, 0.50, 0.78; the largest vertex jump in GeomorphTest's approaches
     * 0.04, 0.02, 0.01 px on the unbounded world and 0.21, 0.16, 0.22 px under the paper's rule); CDLOD's usual
     * morph region is the last third of a level's range.
     */
    public static final double MORPH_SHARE = 0.3;

    private final TerrainQuadtree tree;
    private final Residency residency;
    private final BoundsTree bounds;
    private final int nodeCount;
    private final CopyLattice lattice = new CopyLattice();

    /** Per copy × node: the frame number when the node was in the cut. */
    private int[] stamp = new int[0];
    /** Per copy × node: the node's index in the cut arrays, valid while stamped. */
    private int[] slot = new int[0];
    private int frame;

    private int cutLength;
    private int[] cutNode = new int[0];
    private int[] cutCopy = new int[0];
    private boolean[] cutAlive = new boolean[0];
    /** The node's level distance: its box distance, or its parent's when that is larger ({@link #descend}). */
    private float[] cutDistance = new float[0];
    /** The node's frustum answer, or null when drawing without culling. */
    private Containment[] cutContainment = new Containment[0];

    private final int[] sideLevel = new int[4];
    /** A node's narrowed heights, see {@link #boxDistance}. */
    private final float[] range = new float[2];
    private Vector3fc camera;
    private DetailLimit limit;
    private Visibility visibility;
    /** Copy of the node the last {@link #selectedAt} found. */
    private int foundCopy;

    private int liveCut;
    private int culled;
    private int visited;
    private int forcedSplits;

    /** @param residency which nodes may be split into: only those whose children are all drawable */
    QuadtreeLod(TerrainQuadtree tree, Residency residency) {
        this.tree = tree;
        this.residency = residency;
        this.bounds = tree.bounds();
        this.nodeCount = tree.nodeCount();
    }

    @Override
    public void select(Vector3fc camera, float[] offsets, DetailLimit limit, Visibility visibility, PatchList out) {
        lattice.update(offsets, tree.extent());
        int copies = lattice.copies();
        if (stamp.length < copies * nodeCount) {
            stamp = new int[copies * nodeCount];
            slot = new int[copies * nodeCount];
        }
        if (++frame == 0) {
            Arrays.fill(stamp, 0);
            frame = 1;
        }
        this.camera = camera;
        this.limit = limit;
        this.visibility = visibility;
        cutLength = 0;
        liveCut = 0;
        culled = 0;
        visited = 0;
        forcedSplits = 0;

        // 1. The cut of every copy, by the limit on the box distance.
        for (int copy = 0; copy < copies; copy++) {
            descend(copy, 0, visibility == null ? null : visibility.root(copy), 0);
        }
        // 2. Split coarse nodes that border nodes more than log2 N levels finer (nodes appended here are checked
        //    in turn, so one pass over the growing list settles the whole cut).
        for (int i = 0; i < cutLength; i++) {
            if (cutAlive[i]) {
                limitNeighbourLevels(i);
            }
        }
        // 3. Emit the visible patches with their side and corner levels.
        out.clear();
        for (int i = 0; i < cutLength; i++) {
            if (!cutAlive[i]) {
                continue;
            }
            liveCut++;
            if (cutContainment[i] == Containment.OUTSIDE) {
                culled++;
            } else {
                emit(cutNode[i], cutCopy[i], out);
            }
        }
        this.camera = null;
        this.limit = null;
        this.visibility = null;
    }

    @Override
    public int cutSize() {
        return liveCut;
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
        return forcedSplits;
    }

    /**
     * Adds the node to the cut, or its children when it is not fine enough at its level distance: its box distance,
     * or its parent's when that is larger. A child's box lies within its parent's where the boxes nest (a tile's), so
     * this is the box distance; a streamed world's narrowed boxes need not nest, and the max keeps the level distance
     * growing down the tree, which the morph factor's continuity rests on ({@link #morph}).
     */
    private void descend(int copy, int node, Containment containment, double parentDistance) {
        visited++;
        int level = tree.level(node);
        double distance = Math.max(parentDistance, boxDistance(copy, node));
        if (level > 0 && !limit.fineEnough(level, tree.error(node), distance) && childrenDrawable(copy, node)) {
            int first = bounds.firstChild(node);
            for (int child = first; child < first + 4; child++) {
                descend(copy, child, containment == null ? null : visibility.of(copy, child, containment), distance);
            }
        } else {
            addToCut(copy, node, containment, distance);
        }
    }

    private boolean childrenDrawable(int copy, int node) {
        int first = bounds.firstChild(node);
        for (int child = first; child < first + 4; child++) {
            if (!residency.drawable(child, lattice.offsetX(copy), lattice.offsetZ(copy))) {
                return false;
            }
        }
        return true;
    }

    /**
     * Distance from the camera to the nearest point of the node's box in a copy, metres; the box's heights narrowed
     * to what the node may draw where {@link Residency#heightRange} knows it.
     */
    private double boxDistance(int copy, int node) {
        float offsetX = lattice.offsetX(copy);
        float offsetZ = lattice.offsetZ(copy);
        return residency.heightRange(node, offsetX, offsetZ, range)
                ? bounds.distance(node, offsetX, offsetZ, range[0], range[1], camera)
                : bounds.distance(node, offsetX, offsetZ, camera);
    }

    private void addToCut(int copy, int node, Containment containment, double distance) {
        if (cutLength == cutNode.length) {
            int capacity = Math.max(256, 2 * cutLength);
            cutNode = Arrays.copyOf(cutNode, capacity);
            cutCopy = Arrays.copyOf(cutCopy, capacity);
            cutAlive = Arrays.copyOf(cutAlive, capacity);
            cutContainment = Arrays.copyOf(cutContainment, capacity);
            cutDistance = Arrays.copyOf(cutDistance, capacity);
        }
        int i = cutLength++;
        cutNode[i] = node;
        cutCopy[i] = copy;
        cutAlive[i] = true;
        cutContainment[i] = containment;
        cutDistance[i] = (float) distance;
        stamp[copy * nodeCount + node] = frame;
        slot[copy * nodeCount + node] = i;
    }

    private void limitNeighbourLevels(int i) {
        int node = cutNode[i];
        int copy = cutCopy[i];
        int level = tree.level(node);
        int column = tree.column(node);
        int row = tree.row(node);
        for (Side side : SIDES) {
            int neighbour = selectedAt(copy, level, column + side.dx(), row + side.dz());
            while (neighbour >= 0 && tree.level(neighbour) > level + tree.cellsLog2()) {
                split(foundCopy, neighbour);
                neighbour = selectedAt(copy, level, column + side.dx(), row + side.dz());
            }
        }
    }

    private void split(int copy, int node) {
        int i = slot[copy * nodeCount + node];
        cutAlive[i] = false;
        stamp[copy * nodeCount + node] = 0;
        forcedSplits++;
        Containment containment = cutContainment[i];
        int first = bounds.firstChild(node);
        for (int child = first; child < first + 4; child++) {
            addToCut(copy, child, containment == null ? null : visibility.of(copy, child, containment),
                    Math.max(cutDistance[i], boxDistance(copy, child)));
        }
    }

    /**
     * The cut node covering the node of a level at (column, row) of that level's grid, which may lie one tile
     * outside (then it is looked up in the adjacent copy); sets {@link #foundCopy}.
     *
     * @return the node, or −1 when no copy lies there or the cut is finer than that level there
     */
    private int selectedAt(int copy, int level, int column, int row) {
        int perSide = tree.nodesPerSide(level);
        int dx = column < 0 ? -1 : column >= perSide ? 1 : 0;
        int dz = row < 0 ? -1 : row >= perSide ? 1 : 0;
        int c = dx == 0 && dz == 0 ? copy : lattice.neighbour(copy, dx, dz);
        if (c < 0) {
            return -1;
        }
        int morton = TerrainQuadtree.interleave(column - dx * perSide, row - dz * perSide);
        int depth = tree.rootLevel() - level;
        for (int d = 0; d <= depth; d++) {
            int node = TerrainQuadtree.depthOffset(d) + (morton >>> (2 * (depth - d)));
            if (stamp[c * nodeCount + node] == frame) {
                foundCopy = c;
                return node;
            }
        }
        return -1;
    }

    private void emit(int node, int copy, PatchList out) {
        int level = tree.level(node);
        int column = tree.column(node);
        int row = tree.row(node);
        int i = out.add(node, copy, tree.sampleX(node), tree.sampleZ(node), 1 << level, level, 0);
        out.setMorph(i, morph(copy, node));
        for (Side side : SIDES) {
            int neighbour = selectedAt(copy, level, column + side.dx(), row + side.dz());
            int shared = neighbour < 0 ? level : Math.max(level, tree.level(neighbour));
            sideLevel[side.ordinal()] = shared;
            out.setSide(i, side, shared, shared - level);
            if (neighbour >= 0 && tree.level(neighbour) == shared) {
                out.setSideMorph(i, side, morph(foundCopy, neighbour));
            }
        }
        for (Corner corner : CORNERS) {
            int diagonal = selectedAt(copy, level, column + corner.dx(), row + corner.dz());
            int coarsest = Math.max(sideLevel[corner.northSouth().ordinal()], sideLevel[corner.eastWest().ordinal()]);
            int cornerLevel = diagonal < 0 ? coarsest : Math.max(coarsest, tree.level(diagonal));
            out.setCorner(i, corner, cornerLevel);
            if (diagonal >= 0 && tree.level(diagonal) == cornerLevel) {
                out.setCornerMorph(i, corner, morph(foundCopy, diagonal));
            }
        }
    }

    /**
     * How far a cut node has morphed towards its parent's surface: k = clamp((D − start) / (M(parent) − start), 0, 1)
     * of its level distance D (see {@link #descend}), start = M(parent) − {@link #MORPH_SHARE} · (M(parent) − M(node)),
     * M = {@link DetailLimit#fineFrom}; 0 for a root, which never merges, and a step at M(parent) where
     * M(parent) ≤ M(node).
     */
    private float morph(int copy, int node) {
        int level = tree.level(node);
        if (level >= tree.rootLevel()) {
            return 0;
        }
        double distance = cutDistance[slot[copy * nodeCount + node]];
        int parent = tree.node(level + 1, tree.column(node) >> 1, tree.row(node) >> 1);
        double end = limit.fineFrom(level + 1, tree.error(parent));
        double appears = limit.fineFrom(level, tree.error(node));
        double start = end - MORPH_SHARE * (end - appears);
        if (!(end > start)) {
            return distance >= end ? 1 : 0;
        }
        return (float) Math.max(0, Math.min(1, (distance - start) / (end - start)));
    }
}

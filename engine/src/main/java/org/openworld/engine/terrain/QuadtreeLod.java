package org.openworld.engine.terrain;

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
 * <p>Stitching. A side can zip to a neighbour at most log2 N levels coarser ({@link PatchPatterns}). The paper's rule
 * keeps neighbour differences small when B is large against a leaf patch, but with a tiny B a coarse node can border
 * a much finer one, and the screen-error rule puts a rough node next to a flat one; the cut is then repaired by
 * splitting the coarse node ({@link #forcedSplits()}) until no side sees a difference above log2 N. Then each patch
 * looks up its neighbour across each side and the one across each corner: a side samples the coarser level of the
 * two patches sharing it, a corner the coarsest of the up to four patches touching it, so both patches of a shared
 * vertex fetch the very same height.
 *
 * <p>Geomorphing (CDLOD-style, Strugar 2009). Each drawn node gets a morph range [start, end] of viewer distances.
 * The end is its merge distance M(parent) = {@link DetailLimit#fineFrom} of its parent: from there on the parent is
 * fine enough (paper rule B · 2^(L+1); screen error e_parent · f / p). The vertex shader takes the distance d from
 * the viewer to each vertex and k = clamp((d − start) / (end − start), 0, 1), and moves the vertex's height from its
 * own level's towards the parent's surface there: an even vertex (a parent vertex) to the parent level's height, an
 * odd one to the mean of the parent-level heights of its two even neighbours along its odd axis, or along the cell's
 * diagonal when odd in both (the diagonal {@link PatchPatterns} cuts every cell with), its x and z unchanged. Why it
 * is exact: the parent is drawn only when its box distance reaches M(parent), and no vertex of a node is nearer than
 * its parent's box, so at a merge every vertex of the children has k = 1 and shows the parent's surface. The parent
 * must then show that surface too, with its own k = 0: its start is M(node) + the diagonal of its box, beyond every
 * vertex it has when it appears (the ranges nest: a node's start lies at or beyond its children's end). Where that
 * is beyond the end, start = end and the node steps at its end instead (by at most its parent's error).
 *
 * <p>Shared vertices must agree, so k on an edge is not the patch's own. A side vertex samples the side's level
 * (the coarser patch's); its k is the ramp of the neighbour that samples that level (the coarser neighbour's own
 * range), and when both patches have the same level, the larger of the two ramps: both compute max(k_A, k_B), which
 * is 1 when either merges (so the side is the parent's edge, which the remaining neighbour then reads unmorphed at
 * the parent's k = 0) and equals the remaining patch's ramp when the other has just split (the new children have
 * k = 1 there). A corner takes the largest ramp over the patches touching it that sample its level: the patch
 * itself, its two side neighbours (each side carries its neighbour's range only when that neighbour samples the
 * side's level) and the diagonal one. An edge vertex on a coarser neighbour's level thus morphs with that
 * neighbour, not by itself. The distance is from {@code viewerPos()} to the vertex at the level it samples, so every
 * pass and both patches compute the same d. Limits: the sun's pass chooses its cut from the viewer's eye, as k
 * does, but the reflection's cut is chosen from the mirrored eye, so its merges can step; a node split only to keep neighbours
 * within log2 N levels ({@link #forcedSplits()}) shows its parent's unmorphed surface; the edge strips' fans are not
 * the parent's triangles, so inside a patch's outermost ring of cells k = 1 matches the parent at the vertices only.
 *
 * <p>Cost. The cut is found top-down, touching only the nodes above it. Selected nodes are marked with a per-frame
 * stamp; a neighbour lookup walks from the root towards the same-level node across the side (the node above a
 * given one at any depth is its Morton code shifted, {@link TerrainQuadtree#node}) and stops at the first stamped
 * node: a coarser or equal neighbour, or none above that level, meaning the neighbours there are finer. Nothing is
 * allocated once the arrays have grown to the cut's size.
 */
final class QuadtreeLod implements LodScheme {

    private static final Side[] SIDES = Side.values();
    private static final Corner[] CORNERS = Corner.values();

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
            descend(copy, 0, visibility == null ? null : visibility.root(copy));
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

    private void descend(int copy, int node, Containment containment) {
        visited++;
        int level = tree.level(node);
        if (level > 0 && !limit.fineEnough(level, tree.error(node), boxDistance(copy, node))
                && childrenDrawable(copy, node)) {
            int first = bounds.firstChild(node);
            for (int child = first; child < first + 4; child++) {
                descend(copy, child, containment == null ? null : visibility.of(copy, child, containment));
            }
        } else {
            addToCut(copy, node, containment);
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

    private void addToCut(int copy, int node, Containment containment) {
        if (cutLength == cutNode.length) {
            int capacity = Math.max(256, 2 * cutLength);
            cutNode = Arrays.copyOf(cutNode, capacity);
            cutCopy = Arrays.copyOf(cutCopy, capacity);
            cutAlive = Arrays.copyOf(cutAlive, capacity);
            cutContainment = Arrays.copyOf(cutContainment, capacity);
        }
        int i = cutLength++;
        cutNode[i] = node;
        cutCopy[i] = copy;
        cutAlive[i] = true;
        cutContainment[i] = containment;
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
            addToCut(copy, child, containment == null ? null : visibility.of(copy, child, containment));
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
        out.setMorph(i, morphStart(copy, node), morphEnd(node));
        for (Side side : SIDES) {
            int neighbour = selectedAt(copy, level, column + side.dx(), row + side.dz());
            int shared = neighbour < 0 ? level : Math.max(level, tree.level(neighbour));
            sideLevel[side.ordinal()] = shared;
            out.setSide(i, side, shared, shared - level);
            if (neighbour >= 0 && tree.level(neighbour) == shared) {
                out.setSideMorph(i, side, morphStart(foundCopy, neighbour), morphEnd(neighbour));
            }
        }
        for (Corner corner : CORNERS) {
            int diagonal = selectedAt(copy, level, column + corner.dx(), row + corner.dz());
            int coarsest = Math.max(sideLevel[corner.northSouth().ordinal()], sideLevel[corner.eastWest().ordinal()]);
            int cornerLevel = diagonal < 0 ? coarsest : Math.max(coarsest, tree.level(diagonal));
            out.setCorner(i, corner, cornerLevel);
            if (diagonal >= 0 && tree.level(diagonal) == cornerLevel) {
                out.setCornerMorph(i, corner, morphStart(foundCopy, diagonal), morphEnd(diagonal));
            }
        }
    }

    /** Where a node has merged into its parent, metres: the parent's {@link DetailLimit#fineFrom}; never for the root. */
    private float morphEnd(int node) {
        int level = tree.level(node);
        if (level >= tree.rootLevel()) {
            return PatchList.NEVER;
        }
        int parent = tree.node(level + 1, tree.column(node) >> 1, tree.row(node) >> 1);
        return (float) Math.min(PatchList.NEVER, limit.fineFrom(level + 1, tree.error(parent)));
    }

    /**
     * Where a node starts to morph, metres: beyond every vertex it has when it appears (its own fine-enough distance
     * plus its box's diagonal, the box's heights narrowed where {@link Residency#heightRange} knows them: a streamed
     * world's boxes span all its heights, and a diagonal that long would leave no band), so that it then shows its own
     * surface, as its children did at k = 1; at most its end.
     */
    private float morphStart(int copy, int node) {
        float[] boxes = bounds.boxes();
        int b = 6 * node;
        double dx = boxes[b + 3] - boxes[b];
        double dy = residency.heightRange(node, lattice.offsetX(copy), lattice.offsetZ(copy), range)
                ? range[1] - range[0] : boxes[b + 4] - boxes[b + 1];
        double dz = boxes[b + 5] - boxes[b + 2];
        double appears = limit.fineFrom(tree.level(node), tree.error(node)) + Math.sqrt(dx * dx + dy * dy + dz * dz);
        return (float) Math.min(morphEnd(node), appears);
    }
}

package org.openworld.engine.terrain.lod;

import org.joml.Vector3fc;
import org.openworld.engine.culling.Visibility;

/**
 * Picks the terrain patches to draw each frame with the {@link LodScheme} of the chosen {@link LodMode} (the
 * {@link QuadtreeLod quadtree cut} or the paper's {@link FlatGridLod flat grid}), each as fine as the pass's
 * {@link DetailLimit} asks. GL-free; the renderer reads the
 * result from a {@link PatchList} and draws each patch with the shared {@link org.openworld.engine.terrain.mesh.PatchPatterns}.
 */
public final class PatchSelection {

    private final TerrainQuadtree tree;
    private final QuadtreeLod quadtree;
    /** The paper's flat grid, over a residency that is {@link Residency#whole} only; null otherwise. */
    private final FlatGridLod flatGrid;
    private LodScheme last;
    private int visible;

    /** Patches over a tile whose heights are all on the GPU ({@link Residency#ALL}). */
    public PatchSelection(TerrainQuadtree tree) {
        this(tree, Residency.ALL);
    }

    /**
     * Patches whose nodes are drawn only once {@code residency} has them. The paper's flat grid puts every leaf of
     * every copy in its cut, so it needs every node there ({@link Residency#whole}); over a residency that streams
     * its levels (a tile's worth of leaves for each root of the unbounded world, all at the finest level, most not
     * there) the quadtree stands in for it: {@link LodMode#FLAT_GRID} then draws the quadtree's cut.
     */
    public PatchSelection(TerrainQuadtree tree, Residency residency) {
        this.tree = tree;
        this.quadtree = new QuadtreeLod(tree, residency);
        this.flatGrid = residency.whole() ? new FlatGridLod(tree) : null;
        this.last = quadtree;
    }

    /**
     * Chooses the cut for every copy, computes neighbour and corner levels over the whole cut (visible or not,
     * across copies: a point outside all copies has no neighbour, so nothing to stitch there), and appends to
     * {@code out}, which is cleared first, the patches that {@code visibility} does not place outside.
     *
     * @param camera         eye position, world metres
     * @param offsets        x, z pairs, metres: copy c is drawn at (offsets[2c], offsets[2c + 1]); copies lie on a
     *                       lattice of the tile extent, e.g. the 3 × 3 around the camera, or one copy for a
     *                       non-periodic map
     * @param limit          how fine a patch must be in this pass: the paper's distance rule or a projected error
     * @param visibility     the culling result for the quadtree's {@link TerrainQuadtree#bounds()} with these
     *                       copies, read top-down; null draws everything
     */
    public void select(Vector3fc camera, float[] offsets, DetailLimit limit, LodMode mode, Visibility visibility,
            PatchList out) {
        if (visibility != null
                && (visibility.copies() != offsets.length / 2 || visibility.nodeCount() != tree.nodeCount())) {
            throw new IllegalArgumentException("visibility is for " + visibility.copies() + " copies of "
                    + visibility.nodeCount() + " nodes, not " + offsets.length / 2 + " of " + tree.nodeCount());
        }
        last = switch (mode) {
            case QUADTREE -> quadtree;
            case FLAT_GRID -> flatGrid != null ? flatGrid : quadtree;
        };
        last.select(camera, offsets, limit, visibility, out);
        visible = out.size();
    }

    /** Patches in the last cut, over all copies, visible or not. */
    public int cutSize() {
        return last.cutSize();
    }

    /** Patches the last selection output. */
    public int visiblePatches() {
        return visible;
    }

    /** Patches of the last cut left out as outside the frustum. */
    public int culledPatches() {
        return last.culledPatches();
    }

    /** Quadtree nodes the last selection looked at. */
    public int visitedNodes() {
        return last.visitedNodes();
    }

    /** Nodes the last selection split only to keep neighbour levels within log2 N. */
    public int forcedSplits() {
        return last.forcedSplits();
    }
}

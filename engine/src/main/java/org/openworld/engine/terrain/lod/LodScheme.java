package org.openworld.engine.terrain.lod;

import org.joml.Vector3fc;
import org.openworld.engine.culling.Visibility;

/**
 * A level-of-detail scheme for the terrain: which patches to draw, at which level, and how each side stitches to
 * its neighbours (paper 2.5), each patch as fine as a {@link DetailLimit} asks. Two implementations:
 * {@link FlatGridLod}, the paper's geomipmapping over a fixed grid of patches, and {@link QuadtreeLod}, a quadtree
 * cut, so that distant terrain costs patches in proportion to the logarithm of the world size, not its area.
 * {@link PatchSelection} picks one by {@link LodMode}.
 */
interface LodScheme {

    /**
     * Chooses the patches of every copy, their levels and their stitching, and appends to {@code out} (cleared
     * first) those that {@code visibility} does not place outside. See {@link PatchSelection#select}.
     */
    void select(Vector3fc camera, float[] offsets, DetailLimit limit, Visibility visibility, PatchList out);

    /** Patches in the last selection's cut, over all copies, visible or not. */
    int cutSize();

    /** Patches of the cut left out because their node, or an ancestor, was outside the frustum. */
    int culledPatches();

    /** Quadtree nodes the last selection looked at. */
    int visitedNodes();

    /** Nodes the last selection split only to keep neighbour levels within log2 N (0 where that cannot happen). */
    int forcedSplits();
}

package org.openworld.engine.terrain;

import org.joml.Vector3fc;
import org.openworld.engine.culling.Visibility;

/**
 * A level-of-detail policy for the terrain: which patches to draw, at which level, and how each side stitches to
 * its neighbours (paper 2.5). Two implementations: {@link FlatGridLod}, the paper's geomipmapping over a fixed grid
 * of patches, and {@link QuadtreeLod}, the same rule applied to a quadtree so that distant terrain costs patches in
 * proportion to the logarithm of the world size, not its area. {@link PatchSelection} picks one by {@link LodMode}.
 */
public interface LodRule {

    /**
     * The paper's equation 2, L_B(D) = ⌊log2(D / B)⌋, clamped at 0 (nearer than 2B a patch is drawn at full
     * resolution; no level is finer than the height samples). Exact: ⌊log2⌋ is read from the double's exponent.
     *
     * @param distance       D, metres
     * @param baseResolution B, metres, positive
     */
    static int level(double distance, double baseResolution) {
        double ratio = distance / baseResolution;
        return ratio < 2 ? 0 : Math.getExponent(ratio);
    }

    /**
     * Chooses the patches of every copy, their levels and their stitching, and appends to {@code out} (cleared
     * first) those that {@code visibility} does not place outside. See {@link PatchSelection#select}.
     */
    void select(Vector3fc camera, float[] offsets, double baseResolution, Visibility visibility, PatchList out);

    /** Patches in the last selection's cut, over all copies, visible or not. */
    int cutSize();

    /** Patches of the cut left out because their node, or an ancestor, was outside the frustum. */
    int culledPatches();

    /** Quadtree nodes the last selection looked at. */
    int visitedNodes();

    /** Nodes the last selection split only to keep neighbour levels within log2 N (0 where that cannot happen). */
    int forcedSplits();
}

package org.openworld.engine.terrain;

/**
 * Whether a quadtree node's heights are on the GPU, so that it may be drawn. A tile's are all there from the start
 * ({@link #ALL}); the unbounded world streams its levels around the camera ({@link HeightClipmap}), and a node whose
 * level has not arrived yet is not split into: its coarser parent is drawn instead, never a hole.
 */
@FunctionalInterface
interface Residency {

    /** Every node of every copy, always: a tile made whole at start. */
    Residency ALL = (node, offsetX, offsetZ) -> true;

    /**
     * @param node    a node of the quadtree
     * @param offsetX where the copy (the root) holding it lies, metres, as {@link PatchSelection#select}'s offsets
     * @param offsetZ likewise
     * @return whether every level the node may sample over its area (its own, the next coarser it morphs to, and
     *         the coarser ones its sides may stitch to) is resident
     */
    boolean drawable(int node, float offsetX, float offsetZ);
}

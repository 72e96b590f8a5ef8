package org.openworld.engine.core;

/**
 * Heights a {@link BoundsTree}'s node spans in one copy, where the owner knows them more tightly than the box it
 * built the tree with. The unbounded world's terrain builds one tree for every root before any height has streamed
 * in, so each box spans the whole world's heights; the streamed blocks under a node (their lowest and highest
 * sample) say which heights it may really draw there. The culling system tests the box with these heights instead of
 * the box's own.
 *
 * <p>A range must hold every height the node and everything drawn below it (its subtree) may draw in that copy, as
 * the box does: the hierarchical test settles a whole subtree with the node's answer.
 */
@FunctionalInterface
public interface NodeHeights {

    /** None known: every box is tested with its own heights. */
    NodeHeights NONE = (node, offsetX, offsetZ, out) -> false;

    /**
     * @param node    a node of the tree
     * @param offsetX where the copy holding it lies, metres, as {@link Cullable#offsets()}
     * @param offsetZ likewise
     * @param out     receives the lowest height in [0] and the highest in [1], metres, when known
     * @return whether they were known (out untouched otherwise)
     */
    boolean range(int node, float offsetX, float offsetZ, float[] out);

    /**
     * Whether anything below the node may be drawn on its own in that copy: false where the owner draws the node
     * itself (or its subtree whole) rather than its children, so that a walk need not descend (the streamed world's
     * nodes whose children's heights have not arrived).
     */
    default boolean splits(int node, float offsetX, float offsetZ) {
        return true;
    }
}

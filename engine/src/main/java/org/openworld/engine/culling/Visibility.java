package org.openworld.engine.culling;

/**
 * What the {@link CullingSystem} found for one {@link Cullable} in the pass being drawn: for every copy of the tree,
 * whether each node's box is outside the pass camera's frustum, partly inside or wholly inside. A component on the
 * cullable's entity, rewritten in every pass before the systems that draw read it.
 *
 * <p>The traversal is hierarchical: a node whose parent is {@link Containment#OUTSIDE} or
 * {@link Containment#INSIDE} is never tested, because it shares its parent's answer. So the result is read top-down,
 * passing the parent's answer in: {@link #of(int, int, Containment)}.
 */
public final class Visibility {

    /** Where a box lies relative to a frustum. */
    public enum Containment {
        /** All eight corners are outside one plane: nothing of the box can be seen. */
        OUTSIDE,
        /** Neither outside nor inside: the box may straddle the frustum (a conservative test's "maybe"). */
        PARTIAL,
        /** All eight corners are inside every plane. */
        INSIDE,
        /**
         * Partly inside, and not descended into: its owner draws nothing below it on its own
         * ({@link org.openworld.engine.core.NodeHeights#splits}), so its subtree is kept whole, unculled, as if it
         * were inside.
         */
        KEPT
    }

    private static final Containment[] VALUES = Containment.values();

    private final int nodeCount;
    private final byte[] states;

    public Visibility(int copies, int nodeCount) {
        this.nodeCount = nodeCount;
        this.states = new byte[copies * nodeCount];
    }

    public int copies() {
        return states.length / nodeCount;
    }

    public int nodeCount() {
        return nodeCount;
    }

    /** Records a tested node's answer. */
    public void set(int copy, int node, Containment containment) {
        states[copy * nodeCount + node] = (byte) containment.ordinal();
    }

    /** The root's answer for a copy (the root is always tested). */
    public Containment root(int copy) {
        return VALUES[states[copy * nodeCount]];
    }

    /**
     * A node's answer, given its parent's: the parent's when that was final (outside, inside or kept), else the
     * node's own test.
     *
     * @param parent the answer for the node's parent (for the root, use {@link #root(int)} instead)
     */
    public Containment of(int copy, int node, Containment parent) {
        return parent == Containment.PARTIAL ? VALUES[states[copy * nodeCount + node]] : parent;
    }
}

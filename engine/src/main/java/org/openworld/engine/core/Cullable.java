package org.openworld.engine.core;

/**
 * A component that asks the culling system ({@code culling.CullingSystem}) to test a {@link BoundsTree} against every
 * pass camera; its answer is the culling's {@code Visibility} on the same entity. The tree may be drawn several times
 * at different horizontal offsets (the terrain draws copies of its periodic tile); each copy is tested on its own.
 *
 * <p>It lives in the core, beside {@link HeightField}, as shared vocabulary: any drawing system may attach one (the
 * terrain does at init and refreshes it in update), and the culling and the shadow read it. Like the height field it
 * is written before every pass's render, so the writers need not be ordered before the readers, and they do not
 * declare it: declared, the terrain's write of it and its read of the culling's {@code Visibility} would be a cycle.
 *
 * @param tree    the boxes, for the copy at offset (0, 0)
 * @param offsets x, z pairs, metres: where each copy is drawn; copy {@code c} is at
 *                ({@code offsets[2c]}, {@code offsets[2c + 1]})
 * @param heights the heights each node spans in each copy where known more tightly than its box
 *                ({@link NodeHeights#NONE}: the boxes' own)
 */
public record Cullable(BoundsTree tree, float[] offsets, NodeHeights heights) {

    /** A tree tested with its boxes' own heights. */
    public Cullable(BoundsTree tree, float[] offsets) {
        this(tree, offsets, NodeHeights.NONE);
    }

    public Cullable {
        if (offsets.length == 0 || offsets.length % 2 != 0) {
            throw new IllegalArgumentException("copy offsets come in x, z pairs, at least one copy");
        }
    }

    public int copies() {
        return offsets.length / 2;
    }
}

package org.openworld.engine.culling;

/**
 * A component that asks the {@link CullingSystem} to test a {@link BoundsTree} against every pass camera. The tree
 * may be drawn several times at different horizontal offsets (the terrain draws copies of its periodic tile); each
 * copy is tested on its own.
 *
 * @param tree    the boxes, for the copy at offset (0, 0)
 * @param offsets x, z pairs, metres: where each copy is drawn; copy {@code c} is at
 *                ({@code offsets[2c]}, {@code offsets[2c + 1]})
 */
public record Cullable(BoundsTree tree, float[] offsets) {

    public Cullable {
        if (offsets.length == 0 || offsets.length % 2 != 0) {
            throw new IllegalArgumentException("copy offsets come in x, z pairs, at least one copy");
        }
    }

    public int copies() {
        return offsets.length / 2;
    }
}

package org.openworld.engine.terrain.lod;

/**
 * Whether a quadtree node's heights are on the GPU, so that it may be drawn, and which heights it spans. A tile's are
 * all there from the start and its boxes are exact ({@link #ALL}); the unbounded world streams its levels around the
 * camera ({@link org.openworld.engine.terrain.stream.HeightClipmap}), and a node whose level has not arrived yet is not split into: its coarser parent is
 * drawn instead, never a hole. Its boxes span the whole world's heights, so where the streamed heights are known
 * they give the level rule a tighter range.
 */
public interface Residency {

    /** Every node of every copy, always, with the heights its box gives: a tile made whole at start. */
    Residency ALL = new Residency() {
        @Override
        public boolean whole() {
            return true;
        }

        @Override
        public boolean drawable(int node, float offsetX, float offsetZ) {
            return true;
        }

        @Override
        public boolean heightRange(int node, float offsetX, float offsetZ, float[] out) {
            return false;
        }
    };

    /**
     * Whether every node of every copy is on the GPU from the start, so that a scheme may draw any of them: the
     * paper's flat grid puts every leaf in its cut ({@link PatchSelection}). False unless a residency says so.
     */
    default boolean whole() {
        return false;
    }

    /**
     * @param node    a node of the quadtree
     * @param offsetX where the copy (the root) holding it lies, metres, as {@link PatchSelection#select}'s offsets
     * @param offsetZ likewise
     * @return whether every level the node may sample over its area (its own, the next coarser it morphs to, and
     *         the coarser ones its sides may stitch to) is resident
     */
    boolean drawable(int node, float offsetX, float offsetZ);

    /**
     * The lowest and highest height the node may draw, into out[0] and out[1], when known more tightly than its
     * box; false (out untouched) otherwise.
     */
    boolean heightRange(int node, float offsetX, float offsetZ, float[] out);
}

package org.openworld.engine.terrain.mesh;

import java.util.Arrays;
import org.joml.Vector3fc;
import org.openworld.engine.core.BoundsTree;
import org.openworld.engine.terrain.lod.PatchList;
import org.openworld.engine.terrain.lod.Residency;

/**
 * The patches of a {@link PatchList} nearest first, by the distance from the eye to each patch's box (its quadtree
 * node's, in its copy of the tile, with the heights the streamed world knows where it knows them). Drawn in this
 * order, a near hill writes its depth before the ground it hides is shaded, so early depth rejection skips the hidden
 * pixels; and the patches wholly beyond a distance form the tail of the order, so they can be drawn by a cheaper
 * program. GL-free; reused from frame to frame, so once warm it allocates nothing.
 *
 * <p>Cost: a sort of one {@code long} per patch (the distance's bits above the patch's index): a few microseconds
 * for the hundred or so patches of a view.
 */
public final class PatchOrder {

    private long[] keys = new long[0];
    private int[] order = new int[0];
    private float[] distance = new float[0];
    private int size;
    /** The heights of the node being measured, when the residency knows them. */
    private final float[] range = new float[2];

    /**
     * Orders the patches of {@code list} by distance from {@code eye}.
     *
     * @param bounds    the quadtree's boxes, indexed by {@link PatchList#node(int)}
     * @param residency the heights a node spans where known more tightly than its box (the unbounded world's boxes
     *                  span the whole world's heights: a camera below its highest peak would find every patch
     *                  around it near)
     * @param offsets   x, z pairs, metres, indexed by {@link PatchList#copy(int)}
     */
    public void sort(PatchList list, BoundsTree bounds, Residency residency, float[] offsets, Vector3fc eye) {
        size = list.size();
        if (keys.length < size) {
            keys = new long[size * 2];
            order = new int[size * 2];
            distance = new float[size * 2];
        }
        for (int i = 0; i < size; i++) {
            int copy = list.copy(i);
            int node = list.node(i);
            float x = offsets[2 * copy];
            float z = offsets[2 * copy + 1];
            distance[i] = (float) (residency.heightRange(node, x, z, range)
                    ? bounds.distance(node, x, z, range[0], range[1], eye) : bounds.distance(node, x, z, eye));
            // a non-negative float's bits order as the float does, so the index rides in the low half
            keys[i] = (long) Float.floatToIntBits(distance[i]) << 32 | i;
        }
        Arrays.sort(keys, 0, size);
        for (int k = 0; k < size; k++) {
            order[k] = (int) keys[k];
        }
    }

    /** Patches ordered by the last {@link #sort}. */
    public int size() {
        return size;
    }

    /** The patch indices, nearest first; valid up to {@link #size()}. Shared, not copied. */
    public int[] order() {
        return order;
    }

    /** How many patches, counted from the nearest, have their box nearer than {@code metres}. */
    public int nearerThan(double metres) {
        int k = 0;
        while (k < size && distance[order[k]] < metres) {
            k++;
        }
        return k;
    }

    /** The distance from the eye to patch {@code i}'s box (an index of the list), metres. */
    float distance(int i) {
        return distance[i];
    }
}

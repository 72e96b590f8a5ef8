package org.openworld.engine.terrain.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.Set;
import java.util.SplittableRandom;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.openworld.engine.core.BoundsTree;
import org.openworld.engine.terrain.lod.PatchList;
import org.openworld.engine.terrain.lod.Residency;

/** The patches nearest first, by the distance to their boxes, over random boxes, copies and eyes (no GL). */
class PatchOrderTest {

    @Test
    void patchesComeNearestFirstByTheDistanceToTheirBoxInTheirCopy() {
        SplittableRandom rng = new SplittableRandom(19);
        PatchOrder order = new PatchOrder();
        for (int trial = 0; trial < 50; trial++) {
            int nodes = 1 + rng.nextInt(200);
            float[] boxes = new float[6 * nodes];
            for (int n = 0; n < nodes; n++) {
                for (int axis = 0; axis < 3; axis++) {
                    float a = (float) rng.nextDouble(-2000, 2000);
                    float b = a + (float) rng.nextDouble(0, 500);
                    boxes[6 * n + axis] = a;
                    boxes[6 * n + 3 + axis] = b;
                }
            }
            BoundsTree bounds = new BoundsTree(boxes, new int[nodes], new int[nodes]);
            float[] offsets = {0, 0, 4096, 0, 0, -4096};
            PatchList list = new PatchList();
            for (int i = 0; i < rng.nextInt(300); i++) {
                list.add(rng.nextInt(nodes), rng.nextInt(3), 0, 0, 1, 0, 0);
            }
            Vector3f eye = new Vector3f((float) rng.nextDouble(-3000, 3000), (float) rng.nextDouble(-100, 900),
                    (float) rng.nextDouble(-3000, 3000));

            order.sort(list, bounds, Residency.ALL, offsets, eye);

            assertEquals(list.size(), order.size());
            Set<Integer> seen = new HashSet<>();
            double previous = 0;
            for (int k = 0; k < order.size(); k++) {
                int i = order.order()[k];
                assertTrue(seen.add(i), "patch " + i + " ordered twice");
                double expected = boxDistance(boxes, list.node(i), offsets[2 * list.copy(i)],
                        offsets[2 * list.copy(i) + 1], eye);
                assertEquals(expected, order.distance(i), 1e-3 * (1 + expected));
                assertTrue(order.distance(i) >= previous, "distance falls at rank " + k);
                previous = order.distance(i);
            }
            double metres = rng.nextDouble(0, 3000);
            int nearer = order.nearerThan(metres);
            for (int k = 0; k < order.size(); k++) {
                assertEquals(k < nearer, order.distance(order.order()[k]) < metres, "rank " + k + " of " + metres + " m");
            }
        }
    }

    /**
     * Where the streamed world knows a node's heights more tightly than its box, the distance is to the box with those
     * heights: boxes spanning the world's heights put a camera 400 m above a valley beside every patch.
     */
    @Test
    void theHeightsAResidencyKnowsReplaceTheBoxes() {
        float[] boxes = {0, -500, 0, 100, 3000, 100, 200, -500, 0, 300, 3000, 100};
        BoundsTree bounds = new BoundsTree(boxes, new int[2], new int[2]);
        Residency knowsNodeOne = new Residency() {
            @Override
            public boolean drawable(int node, float offsetX, float offsetZ) {
                return true;
            }

            @Override
            public boolean heightRange(int node, float offsetX, float offsetZ, float[] out) {
                if (node != 1) {
                    return false;
                }
                out[0] = 100;
                out[1] = 200;
                return true;
            }
        };
        PatchList list = new PatchList();
        list.add(0, 0, 0, 0, 1, 0, 0);
        list.add(1, 0, 0, 0, 1, 0, 0);
        PatchOrder order = new PatchOrder();
        Vector3f eye = new Vector3f(150, 600, 50); // above the gap between the two, below the boxes' tops

        order.sort(list, bounds, knowsNodeOne, new float[] {0, 0}, eye);

        // float boxes (24-bit mantissa): distances of tens to hundreds of metres to 1e-3 m
        assertEquals(50, order.distance(0), 1e-3, "node 0: its box, beside the eye");
        assertEquals(Math.hypot(50, 400), order.distance(1), 1e-3, "node 1: 400 m above its known heights");
        assertEquals(0, order.order()[0]);
    }

    /** Brute force: the distance from the eye to the closest point of the box moved by the copy's offset. */
    private static double boxDistance(float[] boxes, int node, float ox, float oz, Vector3f eye) {
        double[] min = {boxes[6 * node] + ox, boxes[6 * node + 1], boxes[6 * node + 2] + oz};
        double[] max = {boxes[6 * node + 3] + ox, boxes[6 * node + 4], boxes[6 * node + 5] + oz};
        double[] p = {eye.x, eye.y, eye.z};
        double sum = 0;
        for (int axis = 0; axis < 3; axis++) {
            double closest = Math.max(min[axis], Math.min(max[axis], p[axis]));
            sum += (p[axis] - closest) * (p[axis] - closest);
        }
        return Math.sqrt(sum);
    }
}

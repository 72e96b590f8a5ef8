package org.openworld.engine.core;

import org.joml.Vector3fc;

/**
 * A tree of axis-aligned bounding boxes, each node's box containing its children's, in flat arrays so a traversal
 * touches no objects. A system that wants its objects culled (the terrain's quadtree) builds one and attaches it to
 * an entity in a {@link Cullable}; the culling system walks it for every pass camera.
 *
 * <p>Node 0 is the root. The children of node {@code i} are {@code firstChild(i) .. firstChild(i) + childCount(i) - 1};
 * a leaf has no children.
 */
public final class BoundsTree {

    private final float[] boxes;
    private final int[] firstChild;
    private final int[] childCount;

    /**
     * @param boxes      six floats per node: minX, minY, minZ, maxX, maxY, maxZ (metres, world space)
     * @param firstChild index of each node's first child (any value for a leaf)
     * @param childCount number of children of each node, 0 for a leaf
     */
    public BoundsTree(float[] boxes, int[] firstChild, int[] childCount) {
        if (boxes.length != 6 * firstChild.length || childCount.length != firstChild.length) {
            throw new IllegalArgumentException("bounds tree arrays disagree on the node count");
        }
        this.boxes = boxes;
        this.firstChild = firstChild;
        this.childCount = childCount;
    }

    public int nodeCount() {
        return firstChild.length;
    }

    public int firstChild(int node) {
        return firstChild[node];
    }

    public int childCount(int node) {
        return childCount[node];
    }

    /** The six floats of all boxes (minX, minY, minZ, maxX, maxY, maxZ per node); shared, not copied. */
    public float[] boxes() {
        return boxes;
    }

    /**
     * From {@code p} to the nearest point of {@code node}'s box moved by (offsetX, 0, offsetZ) (the box in one copy
     * of a periodic tile), metres; 0 inside. The bound a level-of-detail rule needs, and the order of drawing.
     */
    public double distance(int node, float offsetX, float offsetZ, Vector3fc p) {
        return distance(node, offsetX, offsetZ, boxes[6 * node + 1], boxes[6 * node + 4], p);
    }

    /** As {@link #distance(int, float, float, Vector3fc)}, with the box's heights replaced by {@code minY .. maxY}. */
    public double distance(int node, float offsetX, float offsetZ, float minY, float maxY, Vector3fc p) {
        int b = 6 * node;
        double dx = Math.max(0, Math.max(boxes[b] + offsetX - p.x(), p.x() - boxes[b + 3] - offsetX));
        double dy = Math.max(0, Math.max(minY - p.y(), p.y() - maxY));
        double dz = Math.max(0, Math.max(boxes[b + 2] + offsetZ - p.z(), p.z() - boxes[b + 5] - offsetZ));
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}

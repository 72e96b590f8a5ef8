package org.openworld.engine.drainage;

/**
 * A min-heap of grid cells by height, for the priority-flood: each entry one {@code long}, the height's bits made
 * to sort as the heights do in the high half and the cell in the low half, so equal heights leave in the order of
 * their cells and the fill is the same on every run. {@code log2 n} swaps a push or pop; no objects per cell.
 */
final class CellQueue {

    private final long[] heap;
    private int size;

    /** A queue that holds at most {@code capacity} cells at once. */
    CellQueue(int capacity) {
        heap = new long[capacity];
    }

    boolean isEmpty() {
        return size == 0;
    }

    void push(float height, int cell) {
        long key = (long) sortable(height) << 32 | (cell & 0xffffffffL);
        int i = size++;
        while (i > 0) {
            int parent = (i - 1) >>> 1;
            if (heap[parent] <= key) {
                break;
            }
            heap[i] = heap[parent];
            i = parent;
        }
        heap[i] = key;
    }

    /** Takes out the lowest cell (of equal heights, the lowest index) and returns it. */
    int pop() {
        long top = heap[0];
        long last = heap[--size];
        int i = 0;
        while (true) {
            int child = 2 * i + 1;
            if (child >= size) {
                break;
            }
            if (child + 1 < size && heap[child + 1] < heap[child]) {
                child++;
            }
            if (heap[child] >= last) {
                break;
            }
            heap[i] = heap[child];
            i = child;
        }
        heap[i] = last;
        return (int) top;
    }

    /**
     * An int whose signed order is the float's order: positive floats keep their bits (already ordered), negative
     * ones get their magnitude bits flipped, so a larger magnitude sorts lower.
     */
    private static int sortable(float height) {
        int bits = Float.floatToIntBits(height);
        return bits ^ (bits >> 31 & 0x7fffffff);
    }
}

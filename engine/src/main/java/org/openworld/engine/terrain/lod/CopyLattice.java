package org.openworld.engine.terrain.lod;

import java.util.Arrays;

/**
 * Which copy of the terrain tile lies next to which. Copies sit on a lattice of the tile's extent (the 3 × 3 around
 * the camera for a periodic map, one copy for an imported map); a patch at a tile's edge has its neighbour in the
 * adjacent copy, or none when no copy is drawn there. Rebuilt per selection from the offsets; grows, never shrinks.
 */
public final class CopyLattice {

    /**
     * How far from the camera's tile copies of a periodic tile are drawn, metres: where the ground's detail has
     * faded into the air; beyond them the {@code FarField} carries the ground on to the horizon.
     */
    public static final double COPY_DISTANCE = 12_000;

    /** The 3 × 3 steps (dx, dz) ∈ {−1, 0, 1}², row-major. */
    private static final int STEPS = 9;

    private float[] offsets = new float[0];
    private int copies;
    private int[] cellX = new int[0];
    private int[] cellZ = new int[0];
    private int[] neighbours = new int[0];

    /**
     * @param offsets x, z pairs, metres: where each copy is drawn, multiples of the extent
     * @param extent  side of the tile, metres
     */
    void update(float[] offsets, double extent) {
        if (offsets.length == 0 || offsets.length % 2 != 0) {
            throw new IllegalArgumentException("copy offsets come in x, z pairs, at least one copy");
        }
        this.offsets = offsets;
        this.copies = offsets.length / 2;
        if (cellX.length < copies) {
            cellX = new int[copies];
            cellZ = new int[copies];
            neighbours = new int[copies * STEPS];
        }
        for (int c = 0; c < copies; c++) {
            cellX[c] = (int) Math.round(offsets[2 * c] / extent);
            cellZ[c] = (int) Math.round(offsets[2 * c + 1] / extent);
        }
        Arrays.fill(neighbours, 0, copies * STEPS, -1);
        for (int c = 0; c < copies; c++) {
            for (int other = 0; other < copies; other++) {
                int dx = cellX[other] - cellX[c];
                int dz = cellZ[other] - cellZ[c];
                if (Math.abs(dx) <= 1 && Math.abs(dz) <= 1) {
                    neighbours[c * STEPS + (dz + 1) * 3 + dx + 1] = other;
                }
            }
        }
    }

    int copies() {
        return copies;
    }

    float offsetX(int copy) {
        return offsets[2 * copy];
    }

    float offsetZ(int copy) {
        return offsets[2 * copy + 1];
    }

    /** The copy one tile away in direction (dx, dz), each −1, 0 or 1; −1 when none is drawn there. */
    int neighbour(int copy, int dx, int dz) {
        return neighbours[copy * STEPS + (dz + 1) * 3 + dx + 1];
    }

    /**
     * The offsets, metres, of the copies (roots) on a square of {@code radius} around copy (cx, cz), each
     * {@code extent} a side: x, z pairs, row by row from the north-west.
     */
    public static float[] copies(long cx, long cz, int radius, double extent) {
        int side = 2 * radius + 1;
        float[] offsets = new float[2 * side * side];
        int c = 0;
        for (int dz = -radius; dz <= radius; dz++) {
            for (int dx = -radius; dx <= radius; dx++) {
                offsets[c++] = (float) ((cx + dx) * extent);
                offsets[c++] = (float) ((cz + dz) * extent);
            }
        }
        return offsets;
    }
}

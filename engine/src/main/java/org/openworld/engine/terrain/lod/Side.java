package org.openworld.engine.terrain.lod;

/**
 * A side of a square terrain patch. Patches lie in the XZ plane with X east and Z south, so north is −Z: in a
 * patch's vertex grid row 0 is the north side, column N the east side, row N the south side and column 0 the west
 * side.
 */
public enum Side {
    NORTH(0, -1),
    EAST(1, 0),
    SOUTH(0, 1),
    WEST(-1, 0);

    private static final Side[] VALUES = values();

    private final int dx;
    private final int dz;

    Side(int dx, int dz) {
        this.dx = dx;
        this.dz = dz;
    }

    /** Step in X (column) to the neighbour across this side: −1, 0 or +1. */
    public int dx() {
        return dx;
    }

    /** Step in Z (row) to the neighbour across this side: −1, 0 or +1. */
    public int dz() {
        return dz;
    }

    /** The side a neighbour across this side shares with us. */
    public Side opposite() {
        return VALUES[(ordinal() + 2) % 4];
    }
}

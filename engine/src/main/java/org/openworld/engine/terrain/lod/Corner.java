package org.openworld.engine.terrain.lod;

/**
 * A corner of a square terrain patch, where two {@link Side}s meet. In a patch's vertex grid of N cells per side the
 * corners are, as (column, row): north-west (0, 0), north-east (N, 0), south-east (N, N), south-west (0, N).
 */
public enum Corner {
    NORTH_WEST(Side.NORTH, Side.WEST),
    NORTH_EAST(Side.NORTH, Side.EAST),
    SOUTH_EAST(Side.SOUTH, Side.EAST),
    SOUTH_WEST(Side.SOUTH, Side.WEST);

    private final Side northSouth;
    private final Side eastWest;

    Corner(Side northSouth, Side eastWest) {
        this.northSouth = northSouth;
        this.eastWest = eastWest;
    }

    /** The north or south side this corner lies on. */
    public Side northSouth() {
        return northSouth;
    }

    /** The east or west side this corner lies on. */
    public Side eastWest() {
        return eastWest;
    }

    /** Step in X towards the diagonal neighbour: −1 or +1. */
    public int dx() {
        return eastWest.dx();
    }

    /** Step in Z towards the diagonal neighbour: −1 or +1. */
    public int dz() {
        return northSouth.dz();
    }

    /** The corner's column in a grid of {@code cells} cells per side: 0 or {@code cells}. */
    public int column(int cells) {
        return dx() > 0 ? cells : 0;
    }

    /** The corner's row in a grid of {@code cells} cells per side: 0 or {@code cells}. */
    public int row(int cells) {
        return dz() > 0 ? cells : 0;
    }
}

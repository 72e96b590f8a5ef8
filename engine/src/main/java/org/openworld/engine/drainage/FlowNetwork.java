package org.openworld.engine.drainage;

/**
 * Where water runs on a grid of heights: pits filled, each cell's steepest-descent receiver among its eight
 * neighbours (D8), and what flows through each cell, its drainage area and the longest flow path that reaches it.
 * The method is in the package comment; this class holds the result.
 *
 * <p>A grid is {@code width × depth} cells, row-major ({@code z} rows of {@code x} columns), {@code dx} metres apart
 * along x and {@code dz} along z (a geographic DEM's cells are not square). Water leaves at the outlets: on an open
 * grid its border cells; on a periodic one (a tile whose edges continue into the opposite ones) the cells marked as
 * outlets, the sea.
 */
public final class FlowNetwork {

    /** The receiver of an outlet: the water leaves the grid there. */
    public static final int OUTLET = -1;
    /** Neighbour offsets, x then z: the four sides first, then the diagonals. */
    private static final int[] DX = {1, -1, 0, 0, 1, -1, 1, -1};
    private static final int[] DZ = {0, 0, 1, -1, 1, 1, -1, -1};

    private final int width;
    private final int depth;
    private final double dx;
    private final double dz;
    private final boolean periodic;
    private final float[] filled;
    private final boolean[] raised;
    private final boolean[] outlet;
    private final int[] receiver;
    private final int[] order;
    private final double[] area;
    private final double[] length;

    private FlowNetwork(int width, int depth, double dx, double dz, boolean periodic, float[] heights,
            boolean[] outlets) {
        this.width = width;
        this.depth = depth;
        this.dx = dx;
        this.dz = dz;
        this.periodic = periodic;
        int n = width * depth;
        filled = new float[n];
        raised = new boolean[n];
        receiver = new int[n];
        order = new int[n];
        outlet = outlets;
        fill(heights);
        route();
        area = new double[n];
        length = new double[n];
        accumulate();
    }

    /**
     * The network of an open grid: water leaves at its border.
     *
     * @param heights {@code width · depth} heights in metres, row-major; not changed
     */
    public static FlowNetwork open(float[] heights, int width, int depth, double dx, double dz) {
        return open(heights, width, depth, dx, dz, new boolean[heights.length]);
    }

    /**
     * The network of an open grid: water leaves at its border and at the marked outlets (the sea).
     *
     * @param heights {@code width · depth} heights in metres, row-major; not changed
     * @param outlets cells where the water leaves besides the border, {@code width · depth}; not changed
     */
    public static FlowNetwork open(float[] heights, int width, int depth, double dx, double dz, boolean[] outlets) {
        check(heights, width, depth, dx, dz, outlets);
        boolean[] marked = outlets.clone(); // kept by the network
        for (int z = 0; z < depth; z++) {
            for (int x = 0; x < width; x++) {
                marked[z * width + x] |= x == 0 || z == 0 || x == width - 1 || z == depth - 1;
            }
        }
        return new FlowNetwork(width, depth, dx, dz, false, heights, marked);
    }

    /**
     * The network of a periodic grid, whose neighbours wrap across its edges: water leaves at the marked outlets
     * (the sea), or at the lowest cell if none is marked.
     *
     * @param heights {@code width · depth} heights in metres, row-major; not changed
     * @param outlets cells where the water leaves, {@code width · depth}; not changed
     */
    public static FlowNetwork periodic(float[] heights, int width, int depth, double dx, double dz,
            boolean[] outlets) {
        check(heights, width, depth, dx, dz, outlets);
        boolean[] marked = outlets.clone(); // kept by the network
        boolean any = false;
        int lowest = 0;
        for (int i = 0; i < heights.length; i++) {
            any |= marked[i];
            lowest = heights[i] < heights[lowest] ? i : lowest;
        }
        if (!any) {
            marked[lowest] = true;
        }
        return new FlowNetwork(width, depth, dx, dz, true, heights, marked);
    }

    private static void check(float[] heights, int width, int depth, double dx, double dz, boolean[] outlets) {
        if (width < 3 || depth < 3 || heights.length != width * depth) {
            throw new IllegalArgumentException("a flow grid needs at least 3 × 3 cells and one height per cell, got "
                    + width + " × " + depth + " and " + heights.length + " heights");
        }
        if (!(dx > 0 && dz > 0)) {
            throw new IllegalArgumentException("cell spacing must be positive, got " + dx + " × " + dz);
        }
        if (outlets.length != heights.length) {
            throw new IllegalArgumentException("outlets must have one flag per cell, got " + outlets.length);
        }
    }

    /**
     * Priority-flood with ε (Barnes, Lehman and Mulla 2014): from the outlets inwards, lowest first, each cell
     * reached is raised to just above the cell it was reached from if it lies lower, so every cell but an outlet
     * has a neighbour strictly lower. The order cells leave the queue is ascending in filled height, the order
     * {@link #order} keeps, reversed.
     */
    private void fill(float[] heights) {
        int n = width * depth;
        boolean[] closed = new boolean[n];
        CellQueue queue = new CellQueue(n);
        for (int i = 0; i < n; i++) {
            if (outlet[i]) {
                filled[i] = heights[i];
                closed[i] = true;
                queue.push(filled[i], i);
            }
        }
        int popped = 0;
        while (!queue.isEmpty()) {
            int c = queue.pop();
            order[n - 1 - popped++] = c;
            int cx = c % width;
            int cz = c / width;
            for (int k = 0; k < DX.length; k++) {
                int nb = neighbour(cx + DX[k], cz + DZ[k]);
                if (nb < 0 || closed[nb]) {
                    continue;
                }
                closed[nb] = true;
                float floor = Math.nextUp(filled[c]);
                raised[nb] = heights[nb] < floor;
                filled[nb] = raised[nb] ? floor : heights[nb];
                queue.push(filled[nb], nb);
            }
        }
    }

    /** D8: each cell but an outlet drains to the neighbour of the steepest drop per metre, on the filled heights. */
    private void route() {
        for (int i = 0; i < receiver.length; i++) {
            receiver[i] = OUTLET;
        }
        for (int c = 0; c < filled.length; c++) {
            int cx = c % width;
            int cz = c / width;
            if (outlet[c]) {
                continue;
            }
            double steepest = 0;
            for (int k = 0; k < DX.length; k++) {
                int nb = neighbour(cx + DX[k], cz + DZ[k]);
                double drop = nb < 0 ? 0 : (filled[c] - (double) filled[nb]) / step(k);
                if (drop > steepest) {
                    steepest = drop;
                    receiver[c] = nb;
                }
            }
        }
    }

    /** Drainage area and longest upstream path: every cell before its receiver (highest first). */
    private void accumulate() {
        double cellArea = dx * dz;
        for (int c : order) {
            area[c] += cellArea;
            int r = receiver[c];
            if (r != OUTLET) {
                area[r] += area[c];
                length[r] = Math.max(length[r], length[c] + distance(c, r));
            }
        }
    }

    private int neighbour(int x, int z) {
        if (periodic) {
            return Math.floorMod(z, depth) * width + Math.floorMod(x, width);
        }
        return x < 0 || z < 0 || x >= width || z >= depth ? -1 : z * width + x;
    }

    private double step(int k) {
        return k < 2 ? dx : k < 4 ? dz : Math.hypot(dx, dz);
    }

    /** Metres from a cell to its receiver, a neighbour (sides dx or dz, diagonals their hypotenuse). */
    public double distance(int cell, int neighbour) {
        int ddx = Math.abs(cell % width - neighbour % width);
        int ddz = Math.abs(cell / width - neighbour / width);
        boolean alongX = ddx == 1 || ddx == width - 1;
        boolean alongZ = ddz == 1 || ddz == depth - 1;
        return alongX && alongZ ? Math.hypot(dx, dz) : alongX ? dx : dz;
    }

    public int width() {
        return width;
    }

    public int depth() {
        return depth;
    }

    public double dx() {
        return dx;
    }

    public double dz() {
        return dz;
    }

    /** The heights with every pit filled, ε above their spill points; shared, not copied. */
    public float[] filled() {
        return filled;
    }

    /** Whether the cell is an outlet, where the water leaves the grid. */
    public boolean outlet(int cell) {
        return outlet[cell];
    }

    /** Whether the fill raised the cell: it lies in a filled pit (a lake, if the water stood). */
    public boolean raised(int cell) {
        return raised[cell];
    }

    /** The cell's D8 receiver, or {@link #OUTLET}. */
    public int receiver(int cell) {
        return receiver[cell];
    }

    /** Every cell, each before its receiver (highest filled height first); shared, not copied. */
    public int[] order() {
        return order;
    }

    /** Drainage area of the cell, its own included, m². */
    public double area(int cell) {
        return area[cell];
    }

    /** Length of the longest flow path from a divide down to the cell, m (0 on a divide). */
    public double length(int cell) {
        return length[cell];
    }

    /** Slope from the cell down to its receiver on the filled heights, m/m; 0 at an outlet. */
    public double slope(int cell) {
        int r = receiver[cell];
        return r == OUTLET ? 0 : (filled[cell] - (double) filled[r]) / distance(cell, r);
    }
}

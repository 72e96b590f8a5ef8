package org.openworld.engine.drainage;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class FlowNetworkTest {

    /** Floating sums of a few cells of 1 m²: exact but for rounding. */
    private static final double EXACT = 1e-9;

    /**
     * A V-shaped valley on a 5 × 5 grid, 1 m cells, draining south along its axis x = 2: z = 10 |x − 2| + row.
     * Worked by hand: the flanks (x = 1, 3) drop 10 m in 1 m into the axis, more than the 11 m in √2 m to the axis's
     * next cell down or the 1 m to the flank's own border cell; the axis drops 1 m a row. The border cells are
     * outlets. So the axis cell of row 3 gathers itself and the two flanks beside it (3 m²), row 2 that and its own
     * three (6 m²), row 1 nine, and the border cell below it ten.
     */
    @Test
    void valleyAreasAndLengthsByHand() {
        int n = 5;
        float[] h = new float[n * n];
        for (int z = 0; z < n; z++) {
            for (int x = 0; x < n; x++) {
                h[z * n + x] = 10 * Math.abs(x - 2) + z;
            }
        }
        FlowNetwork net = FlowNetwork.open(h, n, n, 1, 1);
        for (int z = 1; z <= 3; z++) {
            assertEquals(z * n + 2, net.receiver(z * n + 1), "west flank of row " + z + " drains into the axis");
            assertEquals(z * n + 2, net.receiver(z * n + 3), "east flank of row " + z + " drains into the axis");
            assertEquals((z - 1) * n + 2, net.receiver(z * n + 2), "axis of row " + z + " drains south");
        }
        assertEquals(3, net.area(3 * n + 2), EXACT);
        assertEquals(6, net.area(2 * n + 2), EXACT);
        assertEquals(9, net.area(n + 2), EXACT);
        assertEquals(10, net.area(2), EXACT);
        assertEquals(FlowNetwork.OUTLET, net.receiver(2));
        // longest path to row 1's axis cell: the flank of row 3 into the axis, then two rows down: 3 m
        assertEquals(3, net.length(n + 2), EXACT);
        assertEquals(1, net.slope(n + 2), EXACT);
    }

    /**
     * A pit: a 5 × 5 dome-less plateau at 10 m whose centre lies at 2 m and whose south border cell at x = 2 lies at
     * 5 m, the spill point. The fill raises the centre just above the lowest way out (the 10 m rim, since the
     * centre's neighbours are all interior at 10 m): every interior cell then drains, nothing is left in a pit.
     */
    @Test
    void pitsAreFilledAndDrain() {
        int n = 5;
        float[] h = new float[n * n];
        java.util.Arrays.fill(h, 10);
        h[2 * n + 2] = 2;
        h[2] = 5;
        FlowNetwork net = FlowNetwork.open(h, n, n, 1, 1);
        assertTrue(net.raised(2 * n + 2), "the pit is raised");
        // the rim is at 10 m: filled strictly above it (by the fill's small epsilon) so water can leave
        assertTrue(net.filled()[2 * n + 2] > 10, "to just above its rim");
        double interior = 0;
        for (int c = 0; c < n * n; c++) {
            int x = c % n;
            int z = c / n;
            if (x > 0 && z > 0 && x < n - 1 && z < n - 1) {
                assertTrue(net.receiver(c) != FlowNetwork.OUTLET, "interior cell " + c + " drains");
                assertTrue(net.filled()[net.receiver(c)] < net.filled()[c], "downhill");
                interior += 1;
            }
        }
        double leaving = 0;
        for (int c = 0; c < n * n; c++) {
            if (net.receiver(c) == FlowNetwork.OUTLET) {
                leaving += net.area(c) - 1; // what reached this outlet from the interior
            }
        }
        assertEquals(interior, leaving, EXACT, "all the interior's water leaves at the outlets");
    }

    /**
     * A tilted plane gives no channels: the flow is parallel, each cell has at most one donor, and the largest
     * drainage area is one row, n − 1 cells long (a row's interior and the border cell it leaves by). Its slope is
     * the same everywhere, so θ is 0.
     */
    @Test
    void planeHasParallelFlowAndNoConcavity() {
        int n = 64;
        double dx = 10;
        float[] h = new float[n * n];
        for (int c = 0; c < n * n; c++) {
            h[c] = (float) (0.1 * dx * (c % n));
        }
        FlowNetwork net = FlowNetwork.open(h, n, n, dx, dx);
        int[] donors = new int[n * n];
        double largest = 0;
        for (int c = 0; c < n * n; c++) {
            if (net.receiver(c) != FlowNetwork.OUTLET) {
                donors[net.receiver(c)]++;
            }
            largest = Math.max(largest, net.area(c));
        }
        assertTrue(java.util.Arrays.stream(donors).max().getAsInt() <= 1, "no cell gathers two");
        assertEquals((n - 1) * dx * dx, largest, EXACT);
        DrainageStats stats = DrainageStats.of(net, h, dx * dx, largest);
        // the slope is 0.1 in every cell up to float rounding of heights near 63 m (4e-6 relative): θ ~ 0
        assertEquals(0, stats.concavity(), 1e-3);
    }

    /** A periodic grid wraps: a valley whose axis crosses the edge drains into the outlet on the other side. */
    @Test
    void periodicGridWrapsAcrossItsEdge() {
        int n = 8;
        float[] h = new float[n * n];
        for (int c = 0; c < n * n; c++) {
            int x = c % n;
            h[c] = Math.min(x, n - x); // lowest along x = 0, rising both ways, wrapping
        }
        boolean[] sea = new boolean[n * n];
        sea[0] = true;
        FlowNetwork net = FlowNetwork.periodic(h, n, n, 1, 1, sea);
        assertEquals(n * n, net.area(0), EXACT, "every cell drains into the one outlet");
        int westOfEdge = 3 * n + n - 1; // x = 7 lies beside x = 0 across the edge
        assertEquals(0, net.receiver(westOfEdge) % n, "the cell west of the edge drains across it");
    }
}

package org.openworld.engine.terrain.material;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The rock's tileable Voronoi diagram against brute force over every point and its copies in the tiles around. */
class PeriodicCellsTest {
    // Tolerances here: doubles: distances in cell units computed two ways agree to round-off; 1e-9 is loose

    private static final int N = 256;
    private static final int COUNT = 5;

    private final PeriodicCells cells = new PeriodicCells(new SplittableRandom(9), N, COUNT);

    /** The copy of point k nearest to (x, y) among those in the 3 × 3 tiles around the central one. */
    private double[] nearestCopy(double x, double y, int k) {
        double[] best = null;
        for (int ty = -1; ty <= 1; ty++) {
            for (int tx = -1; tx <= 1; tx++) {
                double[] copy = {cells.px[k] + tx * N, cells.py[k] + ty * N};
                if (best == null || Math.hypot(x - copy[0], y - copy[1]) < Math.hypot(x - best[0], y - best[1])) {
                    best = copy;
                }
            }
        }
        return best;
    }

    @Test
    void nearestAndEdgeDistanceAgreeWithBruteForce() {
        SplittableRandom random = new SplittableRandom(1);
        for (int q = 0; q < 2000; q++) {
            double x = random.nextDouble() * N;
            double y = random.nextDouble() * N;
            double[] a = null;
            double[] b = null;
            int best = -1;
            for (int k = 0; k < COUNT * COUNT; k++) {
                double[] c = nearestCopy(x, y, k);
                double d = Math.hypot(x - c[0], y - c[1]);
                if (a == null || d < Math.hypot(x - a[0], y - a[1])) {
                    b = a;
                    a = c;
                    best = k;
                } else if (b == null || d < Math.hypot(x - b[0], y - b[1])) {
                    b = c;
                }
            }
            assertEquals(best, cells.nearest(x, y), "nearest cell at (" + x + ", " + y + ")");
            // doubles: distances in cell units computed two ways, equal to round-off (1e-9 is loose)
            assertEquals(Math.hypot(x - a[0], y - a[1]), cells.d1, 1e-9, "d1");
            assertEquals(Math.hypot(x - b[0], y - b[1]), cells.d2, 1e-9, "d2");
            assertEquals(x - a[0], cells.dx, 1e-9, "offset from the nearest point, x");
            assertEquals(y - a[1], cells.dy, 1e-9, "offset from the nearest point, y");
            // the distance to the bisector of the two nearest points: (p − midpoint) · (a − b) / |a − b|
            double ux = a[0] - b[0];
            double uy = a[1] - b[1];
            double bisector = ((x - (a[0] + b[0]) / 2) * ux + (y - (a[1] + b[1]) / 2) * uy) / Math.hypot(ux, uy);
            assertEquals(bisector, cells.edgeDistance(), 1e-9, "distance to the edge");
        }
    }

    @Test
    void theDiagramRepeatsEveryTile() {
        SplittableRandom random = new SplittableRandom(2);
        for (int q = 0; q < 500; q++) {
            double x = random.nextDouble() * N;
            double y = random.nextDouble() * N;
            int k = cells.nearest(x, y);
            double edge = cells.edgeDistance();
            assertEquals(k, cells.nearest(x + N, y), "one tile east");
            assertEquals(edge, cells.edgeDistance(), 1e-9);
            assertEquals(k, cells.nearest(x, y - N), "one tile north");
            assertEquals(edge, cells.edgeDistance(), 1e-9);
        }
    }

    @Test
    void theEdgeDistanceIsZeroHalfwayBetweenNeighbouringPoints() {
        int a = 0;
        int b = 1; // the next cell east
        double mx = (cells.px[a] + cells.px[b]) / 2;
        double my = (cells.py[a] + cells.py[b]) / 2;
        cells.nearest(mx, my);
        assertEquals(0, cells.edgeDistance(), 1e-9);
        // a step of 1 texel from the midpoint towards a, along the line joining them: 1 texel from the edge
        double len = Math.hypot(cells.px[b] - cells.px[a], cells.py[b] - cells.py[a]);
        assertEquals(a, cells.nearest(mx + (cells.px[a] - cells.px[b]) / len, my + (cells.py[a] - cells.py[b]) / len));
        assertEquals(1, cells.edgeDistance(), 1e-9);
    }
}

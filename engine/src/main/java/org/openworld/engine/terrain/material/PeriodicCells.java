package org.openworld.engine.terrain.material;

import java.util.SplittableRandom;

/**
 * A tileable Voronoi diagram: one jittered point in each cell of a periodic {@code count}² grid over an n-texel tile,
 * with per-cell facet parameters. The rock's blocks and fractures ({@link MaterialRecipes}).
 *
 * <p><b>Method.</b> Point k sits in grid cell (k mod count, k div count) at a random place in the cell's middle 70%,
 * so no two points come closer than 0.3 of a cell. The nearest point to a position is among the 3 × 3 cells around
 * it; a cell index past an edge wraps ({@code floorMod}) and its point is moved by whole tiles
 * ({@code floorDiv · n}) to the copy next to the position, so the diagram is periodic like the noise: the nearest
 * point at x + n is the one at x. The distance to the cell's edge is measured to the bisector of the nearest and the
 * second-nearest point (see {@link #edgeDistance}).
 *
 * <p><b>Cost.</b> 9 squared distances per query and two square roots; the rock asks twice per texel.
 *
 * <p><b>Limits.</b> A point two cells away lies at least 1.15 cells from the query (jitter keeps points in their
 * cells' middles), so the 3 × 3 search misses it only where the two nearest points of the window lie farther than
 * that, which needs several neighbours jittered to their far corners at once: rare (the brute-force test finds no
 * miss in 2000 queries), and such a miss moves an edge, it does not tear the tile. Not thread-safe: a query leaves
 * its answer in fields.
 */
final class PeriodicCells {

    private final int n;
    private final int count;
    /** Per cell: the point (texels), its facet's base height (texels) and slope, tone and light, 0..1. */
    final double[] px, py, base, slopeX, slopeY, tone, light;
    /** After {@link #nearest}: offset of the texel from the nearest point, and the two nearest distances. */
    double dx, dy, d1, d2;
    private double n1x, n1y, n2x, n2y;

    /** {@code count}² cells over a tile of {@code n} texels, drawn from {@code rng} (7 numbers per cell). */
    PeriodicCells(SplittableRandom rng, int n, int count) {
        this.n = n;
        this.count = count;
        int cells = count * count;
        px = new double[cells];
        py = new double[cells];
        base = new double[cells];
        slopeX = new double[cells];
        slopeY = new double[cells];
        tone = new double[cells];
        light = new double[cells];
        double size = (double) n / count;
        for (int k = 0; k < cells; k++) {
            px[k] = (k % count + 0.15 + 0.7 * rng.nextDouble()) * size;
            py[k] = (k / count + 0.15 + 0.7 * rng.nextDouble()) * size;
            base[k] = (rng.nextDouble() - 0.5) * 0.3 * size;        // texels: blocks stand proud or sunk
            double angle = rng.nextDouble() * 2 * Math.PI;
            double tilt = 0.12 + 0.3 * rng.nextDouble();            // 7 to 23 degrees
            slopeX[k] = tilt * Math.cos(angle);
            slopeY[k] = tilt * Math.sin(angle);
            tone[k] = rng.nextDouble();
            light[k] = rng.nextDouble();
        }
    }

    /** The cell whose point is nearest to (x, y), in the periodic tile; sets dx, dy, d1, d2. */
    int nearest(double x, double y) {
        double size = (double) n / count;
        int cx = (int) Math.floor(x / size);
        int cy = (int) Math.floor(y / size);
        d1 = Double.MAX_VALUE;
        d2 = Double.MAX_VALUE;
        int best = 0;
        for (int j = -1; j <= 1; j++) {
            for (int i = -1; i <= 1; i++) {
                int gx = cx + i;
                int gy = cy + j;
                int k = Math.floorMod(gy, count) * count + Math.floorMod(gx, count);
                // the point's copy next to this texel: shift by whole tiles where the index wrapped
                double ox = x - (px[k] + Math.floorDiv(gx, count) * (double) n);
                double oy = y - (py[k] + Math.floorDiv(gy, count) * (double) n);
                double d = ox * ox + oy * oy;     // squared until the two nearest are known
                if (d < d1) {
                    d2 = d1;
                    n2x = n1x;
                    n2y = n1y;
                    d1 = d;
                    n1x = ox;
                    n1y = oy;
                    best = k;
                } else if (d < d2) {
                    d2 = d;
                    n2x = ox;
                    n2y = oy;
                }
            }
        }
        d1 = Math.sqrt(d1);
        d2 = Math.sqrt(d2);
        dx = n1x;
        dy = n1y;
        return best;
    }

    /**
     * Distance to the bisector between the nearest and the second-nearest point of the last {@link #nearest} query,
     * texels: the true distance to the cell's edge there (d2 − d1 would overstate it away from the line joining the
     * points).
     */
    double edgeDistance() {
        // texel offset from points A (nearest) and B: p − A = n1, p − B = n2; B − A = n1 − n2
        double abx = n1x - n2x;
        double aby = n1y - n2y;
        double len = Math.hypot(abx, aby);
        // signed distance of p from the bisector plane, measured towards A: (|p−B|² − |p−A|²) / (2 |B−A|)
        return (d2 * d2 - d1 * d1) / (2 * len);
    }
}

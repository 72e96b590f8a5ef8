package org.openworld.engine.grass;

import java.util.ArrayList;
import java.util.List;

/**
 * Which tufts one frame draws, as instanced draws. The world's plane is cut into cells of {@code cell} metres (one
 * tuft each) and the cells into blocks of {@link #BLOCK} × {@link #BLOCK}, both on the world's grid: a cell's index is
 * {@code floor(x / cell)}, whatever the viewer does, so a tuft keeps its place (and its hash, its look) as the viewer
 * moves. A block is drawn when it reaches within the grass's distance of the eye, holds ground where grass grows
 * ({@link GrassField#range}) and its box meets the camera's frustum; neighbouring drawn blocks of a row of blocks are
 * one {@link Run}, one instanced draw whose instance {@code i} is the cell {@code (i mod wide, i div wide)} from the
 * run's first cell. No tuft has a record: the shader makes it from that index.
 */
final class GrassRuns {

    /** Cells a side of a block: 64 tufts, 3.3 m at the default density. */
    static final int BLOCK = 8;

    /** A world-space box, metres, seen by the camera or not. */
    @FunctionalInterface
    interface Frustum {
        boolean sees(double x0, double y0, double z0, double x1, double y1, double z1);
    }

    /**
     * {@code blocks} neighbouring blocks of one row, from the world's cell ({@code cellX}, {@code cellZ}): {@code wide}
     * cells east by {@link #BLOCK} south.
     */
    record Run(long cellX, long cellZ, int blocks) {

        int wide() {
            return blocks * BLOCK;
        }

        int instances() {
            return blocks * BLOCK * BLOCK;
        }
    }

    private GrassRuns() {
    }

    /**
     * The runs around the eye (x, z) to {@code distance} metres.
     *
     * @param cell   the side of a cell, metres
     * @param tallest the tallest blade, metres: the boxes' top over the highest ground
     */
    static List<Run> plan(double x, double z, double distance, double cell, double tallest, GrassField field,
                          Frustum frustum) {
        double side = BLOCK * cell;
        long bx0 = (long) Math.floor((x - distance) / side);
        long bx1 = (long) Math.floor((x + distance) / side);
        long bz0 = (long) Math.floor((z - distance) / side);
        long bz1 = (long) Math.floor((z + distance) / side);
        List<Run> runs = new ArrayList<>();
        for (long bz = bz0; bz <= bz1; bz++) {
            long first = 0;
            int count = 0;
            for (long bx = bx0; bx <= bx1 + 1; bx++) {
                boolean drawn = bx <= bx1 && drawn(bx * side, bz * side, side, x, z, distance, tallest, field,
                        frustum);
                if (drawn) {
                    if (count == 0) {
                        first = bx;
                    }
                    count++;
                } else if (count > 0) {
                    runs.add(new Run(first * BLOCK, bz * BLOCK, count));
                    count = 0;
                }
            }
        }
        return runs;
    }

    private static boolean drawn(double x0, double z0, double side, double x, double z, double distance,
                                 double tallest, GrassField field, Frustum frustum) {
        double dx = Math.max(0, Math.max(x0 - x, x - (x0 + side)));
        double dz = Math.max(0, Math.max(z0 - z, z - (z0 + side)));
        if (Math.hypot(dx, dz) > distance) {
            return false;
        }
        float[] range = field.range(x0, z0, x0 + side, z0 + side);
        return range != null && frustum.sees(x0, range[0], z0, x0 + side, range[1] + tallest, z0 + side);
    }
}

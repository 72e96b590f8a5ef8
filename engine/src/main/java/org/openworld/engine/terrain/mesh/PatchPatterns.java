package org.openworld.engine.terrain.mesh;

import java.util.Arrays;
import org.openworld.engine.terrain.lod.Side;

/**
 * The index patterns every terrain patch is drawn with: one shared set for all patches, not one mesh per patch
 * (de Boer's geomipmapping, the scheme the paper cites for its stitching, 2.5). All patterns index one vertex grid
 * of (N + 1)² vertices, index {@code row * (N + 1) + column}, column → +X (east), row → +Z (south).
 *
 * <p>A patch drawn with own stride 2^a (only every 2^a-th vertex; a = 0 for quadtree nodes, a = L for the flat
 * grid) is five draws: the {@linkplain #interior(int) interior}, every cell of stride 2^a except the outer ring, and
 * one {@linkplain #edge(Side, int, int) edge strip} per side. A strip is the trapezoid between the patch's side and
 * the inner ring; its inner vertices are at stride 2^a, its outer vertices at the stride 2^b of the coarser of the
 * two patches sharing that side. It is zipped from both rows at once (a fan from each outer vertex to the inner
 * vertices below it), so the side holds vertices only at multiples of 2^b: exactly the vertices the coarse
 * neighbour has there, and no T-junction, whatever the level difference up to log2 N. The four strips meet on the
 * diagonals from the corners to the inner ring, so strips and interior tile the patch exactly.
 *
 * <p>At the coarsest stride (a = log2 N, one cell) there is no inner ring: the north pattern is the triangle
 * north-west, north-east, south-west, the south pattern the other half, and the east and west patterns are empty
 * ({@link #count(int)} 0: draw nothing).
 *
 * <p>Every triangle is counter-clockwise seen from above: for positions (x = column, y = 0, z = row),
 * ((b − a) × (c − a)).y > 0.
 */
public final class PatchPatterns {

    private final int cells;
    private final int maxStrideLog2;
    /** Pattern id of edge(side, a, b) at [(a * (maxStrideLog2 + 1) + b) * 4 + side]; −1 where b < a. */
    private final int[] edgeIds;
    private final int[] first;
    private final int[] count;
    private final int[] indices;

    /** @param cells N, the cells per patch side: a power of two, at least 2 */
    public PatchPatterns(int cells) {
        if (cells < 2 || Integer.bitCount(cells) != 1) {
            throw new IllegalArgumentException("cells per patch side must be a power of two ≥ 2, got " + cells);
        }
        this.cells = cells;
        this.maxStrideLog2 = Integer.numberOfTrailingZeros(cells);
        int levels = maxStrideLog2 + 1;
        int patterns = levels + 4 * levels * (levels + 1) / 2;
        this.first = new int[patterns];
        this.count = new int[patterns];
        this.edgeIds = new int[levels * levels * 4];
        Arrays.fill(edgeIds, -1);

        IntList out = new IntList();
        int id = 0;
        for (int a = 0; a <= maxStrideLog2; a++) {
            first[id] = out.size;
            interiorTriangles(a, out);
            count[id] = out.size - first[id];
            id++;
        }
        for (int a = 0; a <= maxStrideLog2; a++) {
            for (int b = a; b <= maxStrideLog2; b++) {
                for (Side side : Side.values()) {
                    edgeIds[(a * levels + b) * 4 + side.ordinal()] = id;
                    first[id] = out.size;
                    edgeTriangles(side, a, b, out);
                    count[id] = out.size - first[id];
                    id++;
                }
            }
        }
        this.indices = Arrays.copyOf(out.values, out.size);
    }

    /** N, the cells per patch side. */
    public int cells() {
        return cells;
    }

    /** log2 N: the coarsest stride, and the largest level difference a side can stitch. */
    public int maxStrideLog2() {
        return maxStrideLog2;
    }

    /** The interior pattern for own stride 2^strideLog2. */
    public int interior(int strideLog2) {
        if (strideLog2 < 0 || strideLog2 > maxStrideLog2) {
            throw new IllegalArgumentException("stride log2 must lie in 0.." + maxStrideLog2 + ", got " + strideLog2);
        }
        return strideLog2;
    }

    /**
     * The edge strip of one side for own stride 2^strideLog2 and outer stride 2^edgeStrideLog2.
     *
     * @param edgeStrideLog2 from {@code strideLog2} (neighbour as fine or finer) to log2 N
     */
    public int edge(Side side, int strideLog2, int edgeStrideLog2) {
        if (strideLog2 < 0 || edgeStrideLog2 < strideLog2 || edgeStrideLog2 > maxStrideLog2) {
            throw new IllegalArgumentException("need 0 ≤ stride " + strideLog2 + " ≤ edge stride " + edgeStrideLog2
                    + " ≤ " + maxStrideLog2);
        }
        return edgeIds[(strideLog2 * (maxStrideLog2 + 1) + edgeStrideLog2) * 4 + side.ordinal()];
    }

    public int patternCount() {
        return first.length;
    }

    /** All patterns' triangles (three vertex indices each), concatenated: the contents of one element buffer. */
    public int[] indices() {
        return indices;
    }

    /** Position of a pattern's first index in {@link #indices()}. */
    public int first(int pattern) {
        return first[pattern];
    }

    /** Number of indices of a pattern (three per triangle; 0 for the empty strips of the coarsest stride). */
    public int count(int pattern) {
        return count[pattern];
    }

    private void interiorTriangles(int a, IntList out) {
        int s = 1 << a;
        int m = cells >> a;
        for (int j = 1; j < m - 1; j++) {
            for (int i = 1; i < m - 1; i++) {
                int x0 = i * s;
                int x1 = x0 + s;
                int z0 = j * s;
                int z1 = z0 + s;
                triangle(out, x0, z0, x0, z1, x1, z1);
                triangle(out, x0, z0, x1, z1, x1, z0);
            }
        }
    }

    /**
     * Builds the strip in local coordinates (u along the side, v inwards from it; for the north side u = column,
     * v = row) and maps it onto the side.
     */
    private void edgeTriangles(Side side, int a, int b, IntList out) {
        int s = 1 << a;
        int t = 1 << b;
        if (cells >> a == 1) {
            if (side == Side.NORTH || side == Side.SOUTH) {
                localTriangle(out, side, 0, 0, cells, 0, 0, cells);
            }
            return;
        }
        // Outer row: u = 0, t, .., N at v = 0. Inner row: u = s, 2s, .., N − s at v = s (one vertex when the
        // patch is two cells wide). Advance along whichever row's next segment has the smaller midpoint, so each
        // triangle spans the overlap of one outer and one inner segment.
        int outerLast = cells / t;
        int innerLast = cells / s - 2;
        int i = 0;
        int j = 0;
        while (i < outerLast || j < innerLast) {
            int outerMid = (2 * i + 1) * t;
            int innerMid = 2 * s + (2 * j + 1) * s;
            if (j == innerLast || (i < outerLast && outerMid <= innerMid)) {
                localTriangle(out, side, i * t, 0, (i + 1) * t, 0, s + j * s, s);
                i++;
            } else {
                localTriangle(out, side, i * t, 0, s + j * s, s, s + (j + 1) * s, s);
                j++;
            }
        }
    }

    private void localTriangle(IntList out, Side side, int u0, int v0, int u1, int v1, int u2, int v2) {
        triangle(out, column(side, u0, v0), row(side, u0, v0), column(side, u1, v1), row(side, u1, v1),
                column(side, u2, v2), row(side, u2, v2));
    }

    private int column(Side side, int u, int v) {
        return switch (side) {
            case NORTH -> u;
            case EAST -> cells - v;
            case SOUTH -> cells - u;
            case WEST -> v;
        };
    }

    private int row(Side side, int u, int v) {
        return switch (side) {
            case NORTH -> v;
            case EAST -> u;
            case SOUTH -> cells - v;
            case WEST -> cells - u;
        };
    }

    /** Appends a triangle given as (column, row) pairs, wound counter-clockwise seen from above. */
    private void triangle(IntList out, int x0, int z0, int x1, int z1, int x2, int z2) {
        long up = (long) (z1 - z0) * (x2 - x0) - (long) (x1 - x0) * (z2 - z0);
        if (up == 0) {
            throw new IllegalStateException("degenerate triangle in a patch pattern");
        }
        out.add(z0 * (cells + 1) + x0);
        if (up > 0) {
            out.add(z1 * (cells + 1) + x1);
            out.add(z2 * (cells + 1) + x2);
        } else {
            out.add(z2 * (cells + 1) + x2);
            out.add(z1 * (cells + 1) + x1);
        }
    }

    /** A growable int array for building the index list once. */
    private static final class IntList {
        int[] values = new int[1024];
        int size;

        void add(int v) {
            if (size == values.length) {
                values = Arrays.copyOf(values, size * 2);
            }
            values[size++] = v;
        }
    }
}

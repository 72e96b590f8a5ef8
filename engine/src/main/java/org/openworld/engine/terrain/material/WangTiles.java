package org.openworld.engine.terrain.material;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;

/**
 * Quilted Wang tiles (Cohen, Shade, Hiller and Deussen 2003, "Wang Tiles for Image and Texture Generation"): a set of
 * square tiles, each edge carrying a colour, laid so that touching edges share their colour; tiles that agree on an
 * edge have the same texels along it, so any such layout is seamless, and a random one never repeats.
 *
 * <p><b>Colours and diamonds.</b> Two colours for the horizontal edges (north, south) and two for the vertical ones
 * (west, east): the complete set is 2⁴ = 16 tiles. Each colour stands for one sample of the exemplar, an offset into
 * it: in every tile whose edge has that colour, the texels of the triangle between the edge and the tile's centre
 * (half of a diamond centred on the edge) come from the exemplar at that offset, and the neighbour across the edge
 * holds the diamond's other half. The exemplar is periodic and as wide as a tile, so the two halves are one
 * unbroken piece of it: nothing changes across a tile's edge, whichever tiles meet there.
 *
 * <p><b>Cuts.</b> Inside a tile its four diamonds meet along the diagonals. In each quarter of the tile, between
 * the diamond of the horizontal edge and that of the vertical one, the boundary is the minimum-error path
 * ({@link ImageQuilting#minimumPath}) over the anti-diagonals of the quarter: on each, the texel where the texels
 * of the two diamonds differ least (e = Σ (a − b)² over albedo rgb, normal xy, relief, gloss), moving at most one
 * texel from one anti-diagonal to the next and at most {@link #BAND} from the diagonal. The path leaves every
 * texel of the tile's edges to its own diamond (except the four corner texels), so the edges stay shared. Albedo
 * and detail are cut together: one seam serves every map.
 *
 * <p><b>Centres.</b> Four diamonds alone would make every tile a mix of the same four pieces, and a picture of many
 * tiles would repeat them at each tile's shift half of the time. So each tile also gets its own block,
 * {@link #CENTRE} of its side, from an offset of the exemplar apart from the diamonds', chosen among
 * {@link #CANDIDATES} for the least error in its border strips and cut into the diamonds there (as image quilting
 * sews a block into its neighbours). It stays clear of the edges, which keep their diamonds.
 *
 * <p><b>Atlas.</b> The 16 tiles are packed 4 × 4 into one texture, columns by (west, east) colour (0,0), (0,1),
 * (1,1), (1,0) and rows likewise by (north, south): each column's east colour is the next one's west, the last
 * one's the first one's, so the atlas is itself a valid periodic Wang tiling and its mip levels, which blend
 * neighbouring texels, blend those of tiles that may really lie side by side. The shader (material.glsl's
 * {@code MAT_WANG}) hashes each edge's colour from the integer coordinates of the tile grid and reads the tile
 * at the atlas cell those colours name.
 *
 * <p><b>Cost.</b> Per material 64 diagonal cuts over a 256² quarter's 510 anti-diagonals, 16 centre blocks of 8
 * candidates and 4 strip cuts each, and a pass over the 2048² atlas: about half a second for the rock in a test
 * JVM, the three materials in parallel. Memory: a texture four tiles wide, 16 times one tile. Per pixel: one
 * lookup per scale as for the repeated tiles, plus four hashes and explicit derivatives.
 *
 * <p><b>Limits.</b> With two colours an edge shows one of two diamonds, so a picture of many tiles still holds
 * each diamond many times, in a random arrangement instead of a grid; more colours (3⁴ = 81 tiles) would thin it
 * at five times the memory. The four diamonds meet in a point at the corners, where the cut has no room and the
 * seam is straight for a few texels.
 */
final class WangTiles {

    /** Tiles along the atlas's side: the 16 tiles of two colours per edge direction. */
    static final int ATLAS = 4;
    /** Largest distance, in texels along a row, by which a cut may stray from the diagonal. */
    static final int BAND = 48;
    /** Side of each tile's own centre block, as a fraction of the tile: inside it the tile differs from all others. */
    static final double CENTRE = 0.8;
    /** Texels the centre block shares with the diamonds around it, where its seam is cut (as ImageQuilting's). */
    static final int OVERLAP = ImageQuilting.OVERLAP;
    /** Candidate offsets drawn per centre block; the one that agrees best with the diamonds in its strips is kept. */
    static final int CANDIDATES = 8;

    /**
     * The atlas: {@code ATLAS · tile}² RGBA8 albedo and detail texels; each colour's exemplar offset (index 0, 1 the
     * horizontal edges' colours 0 and 1, index 2, 3 the vertical edges' colours 0 and 1); each tile's centre block's
     * offset (index row · ATLAS + column); every seam cut.
     */
    record Atlas(int tile, byte[] albedo, byte[] detail, int[] offsetX, int[] offsetY, int[] centreX, int[] centreY,
                 List<ImageQuilting.Seam> seams) {

        /** Atlas texels per side. */
        int size() {
            return ATLAS * tile;
        }
    }

    private WangTiles() {
    }

    /** The west (or north) colour of atlas column (or row) k: columns (0,0), (0,1), (1,1), (1,0). */
    static int first(int k) {
        return k / 2;
    }

    /** The east (or south) colour of atlas column (or row) k. */
    static int second(int k) {
        return k == 1 || k == 2 ? 1 : 0;
    }

    /**
     * The 16 tiles of one material's exemplar, {@code n}² RGBA8 albedo and detail texels (periodic), packed in the
     * atlas; the colours' offsets drawn with {@code rng}, each at least a quarter of the exemplar from the others so
     * no two diamonds show the same texels: the same exemplar and stream give the same bytes.
     */
    static Atlas build(byte[] albedo, byte[] detail, int n, SplittableRandom rng) {
        int[] ox = new int[4];
        int[] oy = new int[4];
        for (int c = 0; c < 4; c++) {
            boolean apart;
            do {
                ox[c] = rng.nextInt(n);
                oy[c] = rng.nextInt(n);
                apart = true;
                for (int k = 0; k < c; k++) {
                    apart &= Math.abs(centred(ox[c] - ox[k], n)) >= n / 4
                            || Math.abs(centred(oy[c] - oy[k], n)) >= n / 4;
                }
            } while (!apart);
        }
        int size = ATLAS * n;
        byte[] outAlbedo = new byte[size * size * 4];
        byte[] outDetail = new byte[size * size * 4];
        int[] cx = new int[ATLAS * ATLAS];
        int[] cy = new int[ATLAS * ATLAS];
        List<ImageQuilting.Seam> seams = new ArrayList<>();
        for (int row = 0; row < ATLAS; row++) {
            for (int col = 0; col < ATLAS; col++) {
                int[] horizontal = {first(row), second(row)};   // north, south
                int[] vertical = {2 + first(col), 2 + second(col)}; // west, east
                for (int fy = 0; fy < 2; fy++) {
                    for (int fx = 0; fx < 2; fx++) {
                        quarter(albedo, detail, n, ox, oy, horizontal[fy], vertical[fx], fx == 1, fy == 1,
                                col * n, row * n, outAlbedo, outDetail, size, seams);
                    }
                }
                int[] at = centre(albedo, detail, n, ox, oy, col * n, row * n, outAlbedo, outDetail, size, rng,
                        seams);
                cx[row * ATLAS + col] = at[0];
                cy[row * ATLAS + col] = at[1];
            }
        }
        return new Atlas(n, outAlbedo, outDetail, ox, oy, cx, cy, List.copyOf(seams));
    }

    /**
     * Fills one quarter of the tile at (x0, y0) of the atlas: local (a, b) runs from the tile's corner (mirrored by
     * flipX, flipY) to its centre; texels nearer the horizontal edge (b = 0) than the cut take diamond {@code top},
     * the rest diamond {@code side}.
     */
    private static void quarter(byte[] albedo, byte[] detail, int n, int[] ox, int[] oy, int top, int side,
                                boolean flipX, boolean flipY, int x0, int y0, byte[] outAlbedo, byte[] outDetail,
                                int size, List<ImageQuilting.Seam> seams) {
        int h = n / 2;
        int rows = 2 * h - 2; // anti-diagonals d = a + b from 1 to 2h - 2 (d = 0 is the corner texel)
        double[] e = new double[rows * h];
        for (int d = 1; d <= rows; d++) {
            int lo = lowest(d, h);
            int hi = highest(d, h);
            for (int t = 0; t < h; t++) {
                double cost = Double.POSITIVE_INFINITY;
                if (t >= lo && t <= hi) {
                    int x = flipX ? n - 1 - t : t;
                    int y = flipY ? n - 1 - (d - t) : d - t;
                    cost = difference(albedo, detail, n, x + ox[top], y + oy[top], x + ox[side], y + oy[side]);
                }
                e[(d - 1) * h + t] = cost;
            }
        }
        int[] cut = ImageQuilting.minimumPath(e, rows, h);
        int[] diagonal = new int[rows]; // the straight seam: t = (d + 1) / 2, always inside the band
        for (int d = 1; d <= rows; d++) {
            diagonal[d - 1] = (d + 1) / 2;
        }
        seams.add(new ImageQuilting.Seam(ImageQuilting.cost(e, h, cut), ImageQuilting.cost(e, h, diagonal)));
        for (int b = 0; b < h; b++) {
            for (int a = 0; a < h; a++) {
                int d = a + b;
                // on anti-diagonal d, texels from the cut's t on (nearer the horizontal edge) are the top diamond's
                int c = d == 0 ? top : a >= cut[d - 1] ? top : side;
                int x = flipX ? n - 1 - a : a;
                int y = flipY ? n - 1 - b : b;
                int from = 4 * (Math.floorMod(y + oy[c], n) * n + Math.floorMod(x + ox[c], n));
                int to = 4 * ((y0 + y) * size + x0 + x);
                System.arraycopy(albedo, from, outAlbedo, to, 4);
                System.arraycopy(detail, from, outDetail, to, 4);
            }
        }
    }

    /**
     * Quilts the tile at (x0, y0) its own centre: a block {@link #CENTRE} of the tile wide, from the candidate offset
     * whose texels differ least from the tile's in the block's four border strips, cut into them along the
     * minimum-error path of each strip. Candidates within a quarter of the exemplar of a diamond's offset are left
     * out: the exemplar's own continuation would match a diamond perfectly and rebuild it. The block stays clear of
     * the tile's edges, so they keep their diamonds' texels. Returns the offset taken.
     */
    private static int[] centre(byte[] albedo, byte[] detail, int n, int[] ox, int[] oy, int x0, int y0,
                                byte[] outAlbedo, byte[] outDetail, int size, SplittableRandom rng,
                                List<ImageQuilting.Seam> seams) {
        int side = (int) Math.round(CENTRE * n);
        int b0 = (n - side) / 2; // the block's first texel in the tile, along both axes
        int u = 0;
        int v = 0;
        double least = Double.POSITIVE_INFINITY;
        for (int k = 0; k < CANDIDATES; k++) {
            int cu;
            int cv;
            boolean apart;
            do {
                cu = rng.nextInt(n);
                cv = rng.nextInt(n);
                apart = true;
                for (int c = 0; c < 4; c++) {
                    apart &= Math.abs(centred(cu - ox[c], n)) >= n / 4 || Math.abs(centred(cv - oy[c], n)) >= n / 4;
                }
            } while (!apart);
            double error = 0;
            for (int l = 0; l < side; l++) {
                for (int w = 0; w < OVERLAP; w++) {
                    // the left, right, top and bottom strips
                    for (int s = 0; s < 4; s++) {
                        int across = s % 2 == 0 ? w : side - 1 - w;
                        int bx = b0 + (s < 2 ? across : l);
                        int by = b0 + (s < 2 ? l : across);
                        error += placedDifference(albedo, detail, n, outAlbedo, outDetail, size, x0 + bx, y0 + by,
                                cu + bx, cv + by);
                    }
                }
            }
            if (error < least) {
                least = error;
                u = cu;
                v = cv;
            }
        }
        // the strips' cuts: left, right (columns), top, bottom (rows); each along the strip, the texel across it
        int[][] cuts = new int[4][];
        for (int s = 0; s < 4; s++) {
            double[] e = new double[side * OVERLAP];
            for (int l = 0; l < side; l++) {
                for (int w = 0; w < OVERLAP; w++) {
                    int across = s % 2 == 0 ? w : side - OVERLAP + w;
                    int bx = s < 2 ? across : l;
                    int by = s < 2 ? l : across;
                    e[l * OVERLAP + w] = placedDifference(albedo, detail, n, outAlbedo, outDetail, size,
                            x0 + b0 + bx, y0 + b0 + by, u + b0 + bx, v + b0 + by);
                }
            }
            cuts[s] = ImageQuilting.minimumPath(e, side, OVERLAP);
            double straight = Double.POSITIVE_INFINITY;
            for (int w = 0; w < OVERLAP; w++) {
                int[] line = new int[side];
                Arrays.fill(line, w);
                straight = Math.min(straight, ImageQuilting.cost(e, OVERLAP, line));
            }
            seams.add(new ImageQuilting.Seam(ImageQuilting.cost(e, OVERLAP, cuts[s]), straight));
        }
        int far = side - OVERLAP;
        for (int by = 0; by < side; by++) {
            for (int bx = 0; bx < side; bx++) {
                // the diamonds keep the outer side of every cut, the centre block fills the inside
                boolean inside = bx >= cuts[0][by] && bx - far < cuts[1][by]
                        && by >= cuts[2][bx] && by - far < cuts[3][bx];
                if (inside) {
                    int from = 4 * (Math.floorMod(v + b0 + by, n) * n + Math.floorMod(u + b0 + bx, n));
                    int to = 4 * ((y0 + b0 + by) * size + x0 + b0 + bx);
                    System.arraycopy(albedo, from, outAlbedo, to, 4);
                    System.arraycopy(detail, from, outDetail, to, 4);
                }
            }
        }
        return new int[] {u, v};
    }

    /** e between the atlas texel (x, y) as placed and the exemplar's texel (ex, ey) (wrapped). */
    private static double placedDifference(byte[] albedo, byte[] detail, int n, byte[] outAlbedo, byte[] outDetail,
                                           int size, int x, int y, int ex, int ey) {
        return squared(outAlbedo, outDetail, 4 * (y * size + x), albedo, detail,
                4 * (Math.floorMod(ey, n) * n + Math.floorMod(ex, n)));
    }

    /**
     * The cut's lowest texel index a on anti-diagonal d of a quarter of side h: at least 1, so the vertical edge's
     * texel stays with its diamond, within the band, and inside the quarter.
     */
    static int lowest(int d, int h) {
        return Math.max(1, Math.max((d + 1) / 2 - BAND, d - h + 1));
    }

    /** The cut's highest texel index on anti-diagonal d: at most d, so the horizontal edge's texel stays its own. */
    static int highest(int d, int h) {
        return Math.min(d, Math.min(d / 2 + BAND, h - 1));
    }

    /** e: the squared difference of the seven channels of two exemplar texels (wrapped). */
    private static double difference(byte[] albedo, byte[] detail, int n, int x1, int y1, int x2, int y2) {
        return squared(albedo, detail, 4 * (Math.floorMod(y1, n) * n + Math.floorMod(x1, n)), albedo, detail,
                4 * (Math.floorMod(y2, n) * n + Math.floorMod(x2, n)));
    }

    /**
     * The squared difference over the seven channels (albedo rgb, detail rgba; 0..1 each) of texel p of one pair of
     * maps and texel q of another (byte offsets of RGBA8 texels).
     */
    private static double squared(byte[] albedoA, byte[] detailA, int p, byte[] albedoB, byte[] detailB, int q) {
        double sum = 0;
        for (int c = 0; c < 4; c++) {
            if (c < 3) {
                double d = ((albedoA[p + c] & 0xFF) - (albedoB[q + c] & 0xFF)) / 255.0;
                sum += d * d;
            }
            double d = ((detailA[p + c] & 0xFF) - (detailB[q + c] & 0xFF)) / 255.0;
            sum += d * d;
        }
        return sum;
    }

    /** An offset difference brought into −n/2 .. n/2 (the exemplar is periodic). */
    private static int centred(int d, int n) {
        return Math.floorMod(d + n / 2, n) - n / 2;
    }
}

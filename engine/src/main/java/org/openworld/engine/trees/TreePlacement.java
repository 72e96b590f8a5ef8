package org.openworld.engine.trees;

import java.util.Arrays;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.core.BoundsTree;

/**
 * Where the trees stand, on the CPU and without GL: a jittered grid over the whole plane, each cell's tree decided by
 * a hash of the seed and the cell alone, so the same ground always grows the same trees, whatever the camera did
 * before and however often the set around it is rebuilt.
 *
 * <p><b>The grid.</b> Square tiles of {@link #TILE} metres, each cut into n × n cells, n the smallest count whose cells
 * hold at most one tree at the density ({@code cell² · density ≤ 1}). A cell keeps its tree with probability
 * {@code density · cell²}, at a random point inside it: the expected count is exactly density × area, and no two
 * trees crowd closer than chance in a cell allows (a jittered grid, a cheap stand-in for Poisson-disc sampling).
 *
 * <p><b>The rules</b> ({@link Limits}), each read from the height field at the tree's foot: the ground lies above the
 * water plus a shore margin, below the snow line's start, and no steeper than the largest gradient (central
 * differences {@link #PROBE} metres either side).
 *
 * <p><b>The records</b>, {@link #FLOATS} floats per tree, tile by tile: the foot (x, y, z, metres), the height
 * (metres), a turn about the vertical (radians) and a tint (0..1). Every tile also gets a box that holds its trees,
 * for the culling system: the tiles are the leaves of a two-level {@link BoundsTree}.
 */
final class TreePlacement {

    /** Side of a tile, metres: a few dozen trees at the default density, a box the culling can drop whole. */
    static final double TILE = 200;
    static final int FLOATS = 6;
    /** Metres either side of the foot at which the slope is measured: the terrain's 2 m sample spacing. */
    static final double PROBE = 2;
    /** A tree's widest reach from its foot, as a share of its height (the lowest cone's radius, rounded up). */
    static final double REACH = 0.3;

    private TreePlacement() {
    }

    /**
     * Where trees may stand.
     *
     * @param lowest      metres: the lowest foot (the water plus the shore margin; −∞ without water)
     * @param highest     metres: the highest foot (the snow line's start; +∞ without snow)
     * @param maxGradient the steepest ground, rise over run
     */
    record Limits(double lowest, double highest, double maxGradient) {

        boolean allow(double height, double gradient) {
            return height >= lowest && height <= highest && gradient <= maxGradient;
        }
    }

    /**
     * The trees of a disc, tile by tile.
     *
     * @param records     {@link #FLOATS} floats per tree, the tiles' trees one after the other
     * @param tileFirst   the first tree of each tile
     * @param tileCount   the trees of each tile (every tile here has at least one)
     * @param bounds      the root box (node 0) and one box per tile (node t + 1)
     * @param x           where the records' x and z are measured from: the disc's centre, metres
     * @param z           its z
     */
    record Layout(float[] records, int[] tileFirst, int[] tileCount, BoundsTree bounds, double x, double z) {

        /** The records with the feet in world coordinates (tests and tools near the origin: floats). */
        float[] worldRecords() {
            float[] world = records.clone();
            for (int o = 0; o < world.length; o += FLOATS) {
                world[o] = (float) (records[o] + x);
                world[o + 2] = (float) (records[o + 2] + z);
            }
            return world;
        }

        int count() {
            return records.length / FLOATS;
        }

        int tiles() {
            return tileFirst.length;
        }
    }

    /**
     * The trees within {@code radius} of (x, z), their feet's x and z in the records from (x, z) itself (the bounds
     * are the world's): a float then keeps the feet's centimetres however far out they stand.
     *
     * @param seed the world's seed ({@code engine.seed})
     */
    static Layout around(HeightField field, double x, double z, double radius, TreeSettings s, Limits limits,
                         int seed) {
        double perSquareMetre = s.density() / 10_000;
        int cells = (int) Math.ceil(TILE * Math.sqrt(perSquareMetre));
        double cell = TILE / cells;
        double keep = perSquareMetre * cell * cell;
        long t0x = (long) Math.floor((x - radius) / TILE);
        long t1x = (long) Math.floor((x + radius) / TILE);
        long t0z = (long) Math.floor((z - radius) / TILE);
        long t1z = (long) Math.floor((z + radius) / TILE);
        int tilesMax = (int) ((t1x - t0x + 1) * (t1z - t0z + 1));
        float[] records = new float[64 * FLOATS];
        int[] first = new int[tilesMax];
        int[] count = new int[tilesMax];
        float[] boxes = new float[6 * (tilesMax + 1)];
        int trees = 0;
        int tiles = 0;
        for (long tz = t0z; tz <= t1z; tz++) {
            for (long tx = t0x; tx <= t1x; tx++) {
                int start = trees;
                float[] box = {Float.MAX_VALUE, Float.MAX_VALUE, Float.MAX_VALUE,
                    -Float.MAX_VALUE, -Float.MAX_VALUE, -Float.MAX_VALUE};
                for (int j = 0; j < cells; j++) {
                    for (int i = 0; i < cells; i++) {
                        long cx = tx * cells + i;
                        long cz = tz * cells + j;
                        long h = mix(mix(mix(seed) ^ cx) ^ cz);
                        if (unit(h, 0) >= keep) {
                            continue;
                        }
                        double px = (cx + unit(h, 1)) * cell;
                        double pz = (cz + unit(h, 2)) * cell;
                        double dx = px - x;
                        double dz = pz - z;
                        if (dx * dx + dz * dz > radius * radius) {
                            continue;
                        }
                        double ground = field.heightAt(px, pz);
                        if (!limits.allow(ground, gradient(field, px, pz))) {
                            continue;
                        }
                        double height = s.minHeight() + (s.maxHeight() - s.minHeight()) * unit(h, 3);
                        if ((trees + 1) * FLOATS > records.length) {
                            records = Arrays.copyOf(records, 2 * records.length);
                        }
                        int o = trees * FLOATS;
                        records[o] = (float) (px - x);
                        records[o + 1] = (float) ground;
                        records[o + 2] = (float) (pz - z);
                        records[o + 3] = (float) height;
                        records[o + 4] = (float) (2 * Math.PI * unit(h, 4));
                        records[o + 5] = (float) unit(h, 5);
                        grow(box, px, pz, height * REACH, ground - TreeShape.SINK * height, ground + height);
                        trees++;
                    }
                }
                if (trees > start) {
                    first[tiles] = start;
                    count[tiles] = trees - start;
                    System.arraycopy(box, 0, boxes, 6 * (tiles + 1), 6);
                    tiles++;
                }
            }
        }
        return new Layout(Arrays.copyOf(records, trees * FLOATS), Arrays.copyOf(first, tiles),
                Arrays.copyOf(count, tiles), bounds(boxes, tiles), x, z);
    }

    /** The ground's gradient (rise over run) at (x, z), by central differences. */
    static double gradient(HeightField field, double x, double z) {
        double gx = (field.heightAt(x + PROBE, z) - field.heightAt(x - PROBE, z)) / (2 * PROBE);
        double gz = (field.heightAt(x, z + PROBE) - field.heightAt(x, z - PROBE)) / (2 * PROBE);
        return Math.sqrt(gx * gx + gz * gz);
    }

    /** Widens a box (min xyz, max xyz) to hold a tree at (x, z) of this reach, from {@code bottom} to {@code top}. */
    private static void grow(float[] box, double x, double z, double reach, double bottom, double top) {
        box[0] = (float) Math.min(box[0], x - reach);
        box[1] = (float) Math.min(box[1], bottom);
        box[2] = (float) Math.min(box[2], z - reach);
        box[3] = (float) Math.max(box[3], x + reach);
        box[4] = (float) Math.max(box[4], top);
        box[5] = (float) Math.max(box[5], z + reach);
    }

    /** A root holding every tile's box, and the tiles as its leaves; null when no tree stands. */
    private static BoundsTree bounds(float[] boxes, int tiles) {
        if (tiles == 0) {
            return null;
        }
        float[] all = Arrays.copyOf(boxes, 6 * (tiles + 1));
        for (int c = 0; c < 3; c++) {
            all[c] = Float.MAX_VALUE;
            all[3 + c] = -Float.MAX_VALUE;
            for (int t = 1; t <= tiles; t++) {
                all[c] = Math.min(all[c], all[6 * t + c]);
                all[3 + c] = Math.max(all[3 + c], all[6 * t + 3 + c]);
            }
        }
        int[] firstChild = new int[tiles + 1];
        int[] childCount = new int[tiles + 1];
        firstChild[0] = 1;
        childCount[0] = tiles;
        return new BoundsTree(all, firstChild, childCount);
    }

    /** SplitMix64's finaliser: every bit of the input stirs every bit of the output. */
    static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    /** The k-th uniform number in [0, 1) drawn from a cell's hash: 53 bits of a further mix. */
    private static double unit(long hash, int k) {
        return (mix(hash + (k + 1) * 0x9E3779B97F4A7C15L) >>> 11) * 0x1.0p-53;
    }
}

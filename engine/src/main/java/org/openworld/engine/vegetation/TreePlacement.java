package org.openworld.engine.vegetation;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.openworld.engine.core.BoundsTree;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.environment.Moisture;
import org.openworld.engine.environment.SnowLine;

/**
 * Where the plants stand, on the CPU and without GL: a jittered grid over the whole plane, each cell's plant decided
 * by a hash of the seed and the cell and by the {@link PlacementField} at its foot alone, so the same ground always
 * grows the same plants, whichever tile is placed first, on whichever thread, and however often the set around the
 * viewer is rebuilt.
 *
 * <p><b>The grid.</b> Square tiles of {@link #TILE} metres, each cut into n × n cells, n the smallest count whose cells
 * hold at most one plant at the full density ({@code cell² · density ≤ 1}). A cell keeps its plant with probability
 * {@code density · cell² · field(x, z)}, at a random point inside it: the expected count is the density times the
 * field's integral over the area, and no two plants crowd closer than chance in a cell allows (a jittered grid, a
 * cheap stand-in for Poisson-disc sampling; the field's forests and clearings are its clustering).
 *
 * <p><b>The rules</b> ({@link Limits}), each read from the height field at the foot: the ground lies above the water
 * plus a shore margin, below the tree line (half-way up the snow line's fringe), and no steeper than the largest
 * gradient (central differences {@link #PROBE} metres either side). Towards the tree line a plant is also shorter:
 * its height is the settings' times the field's {@link PlacementField#stature}.
 *
 * <p><b>The records</b>, {@link #FLOATS} floats per plant, grouped by kind (all conifers, then broadleaf trees, then
 * bushes), each kind tile by tile: the foot (x, y, z, metres), the height (metres), a turn about the vertical
 * (radians) and a tint (0..1). Every tile also gets a box that holds its plants, for the culling system: the tiles are
 * the leaves of a two-level {@link BoundsTree}.
 *
 * <p><b>Far from the origin.</b> A foot's x and z are never stored as world coordinates: a float 10 000 km out keeps
 * whole metres only. A tile keeps its feet and box from its own corner (under {@link #TILE} metres, tenths of a
 * millimetre), and a layout from its centre, the corner of the tile under the viewer, held in double
 * ({@link Layout#centreX}): the tile's corner from the centre is a whole number of tiles, computed in double, so a
 * foot keeps its centimetres however far out the world is. The drawing adds the centre as the render origin sees it.
 */
final class TreePlacement {

    /** Side of a tile, metres: a few dozen trees at the default density, a box the culling can drop whole. */
    static final double TILE = 200;
    static final int FLOATS = 6;
    static final int KINDS = TreeKind.values().length;
    /** Metres either side of the foot at which the slope is measured: the terrain's 2 m sample spacing. */
    static final double PROBE = 2;

    private TreePlacement() {
    }

    /**
     * Where plants may stand.
     *
     * @param lowest      metres: the lowest foot (the water plus the shore margin; −∞ without water)
     * @param snow        where snow lies (the terrain's {@link SnowLine}); null without snow
     * @param maxGradient the steepest ground, rise over run
     */
    record Limits(double lowest, SnowLine snow, double maxGradient) {

        /**
         * The tree line's share of the way up the snow line's fringe: trees stop where snow is as likely as not
         * ({@link SnowLine#chanceAt} = ½), below the closed snow fields, which the snow map keeps only where snow is
         * near certain; on the default tile 0.475 of the relief, with snow from 0.35 and certain at 0.60.
         */
        static final double TREELINE_CHANCE = 0.5;

        /** Metres: the highest foot, the tree line ({@link #TREELINE_CHANCE} up the snow's fringe; +∞ without snow). */
        double highest() {
            return snow == null ? Double.POSITIVE_INFINITY : snow.start() + TREELINE_CHANCE * (snow.full() - snow.start());
        }

        /** How likely snow lies at {@code height} metres, 0 to 1: the snow line's chance, 0 without snow. */
        double snowChance(double height) {
            return snow == null ? 0 : snow.chanceAt(height);
        }

        boolean allow(double height, double gradient) {
            return height >= lowest && height <= highest() && gradient <= maxGradient;
        }
    }

    /**
     * One tile's plants: {@link #FLOATS} floats each, by kind, and the box holding them all (null when none); feet
     * and box measured from the tile's corner ({@code tx · TILE, tz · TILE}).
     */
    record Tile(long tx, long tz, float[][] records, float[] box) {
    }

    /**
     * The plants of a set of tiles, by kind, tile by tile.
     *
     * @param records   {@link #FLOATS} floats per plant: every tile's conifers, then every tile's broadleaf trees, ...;
     *                  feet measured from the centre
     * @param tileFirst [kind][tile]: the first plant of that kind in that tile
     * @param tileCount [kind][tile]: how many
     * @param bounds    the root box (node 0) and one box per tile (node t + 1), from the centre; null when no plant
     *                  stands
     * @param centreX   metres, world x: where the records' and the boxes' x are measured from (a tile's corner)
     * @param centreZ   metres, world z: as x
     */
    record Layout(float[] records, int[][] tileFirst, int[][] tileCount, BoundsTree bounds, double centreX,
                  double centreZ) {

        static final Layout EMPTY = new Layout(new float[0], new int[KINDS][0], new int[KINDS][0], null, 0, 0);

        /** The records with the feet in world x and z (tests and tools; a float there keeps whole metres far out). */
        float[] worldRecords() {
            float[] world = records.clone();
            for (int o = 0; o < world.length; o += FLOATS) {
                world[o] = (float) (centreX + records[o]);
                world[o + 2] = (float) (centreZ + records[o + 2]);
            }
            return world;
        }

        int count() {
            return records.length / FLOATS;
        }

        int tiles() {
            return tileFirst[0].length;
        }
    }

    /** The plants within the tiles meeting the disc of {@code radius} around (x, z), with no cache (tests, tools). */
    static Layout around(HeightField heights, Moisture moisture, double x, double z, double radius,
                         VegetationSettings s, Limits limits, int seed) {
        PlacementField field = new PlacementField(heights, moisture, limits, seed);
        List<Tile> tiles = new ArrayList<>();
        for (long[] t : tilesAround(x, z, radius)) {
            tiles.add(tile(field, heights, t[0], t[1], s, limits, seed));
        }
        return assemble(tiles, x, z);
    }

    /** The tiles whose square meets the disc of {@code radius} around (x, z), row by row. */
    static List<long[]> tilesAround(double x, double z, double radius) {
        List<long[]> tiles = new ArrayList<>();
        for (long tz = (long) Math.floor((z - radius) / TILE); tz <= (long) Math.floor((z + radius) / TILE); tz++) {
            for (long tx = (long) Math.floor((x - radius) / TILE); tx <= (long) Math.floor((x + radius) / TILE); tx++) {
                double dx = Math.max(0, Math.max(tx * TILE - x, x - (tx + 1) * TILE));
                double dz = Math.max(0, Math.max(tz * TILE - z, z - (tz + 1) * TILE));
                if (dx * dx + dz * dz <= radius * radius) {
                    tiles.add(new long[] {tx, tz});
                }
            }
        }
        return tiles;
    }

    /** One tile's plants: a function of the tile, the seed, the settings and the land alone. */
    static Tile tile(PlacementField field, HeightField heights, long tx, long tz, VegetationSettings s, Limits limits,
                     int seed) {
        float[][] records = new float[KINDS][];
        int[] counts = new int[KINDS];
        for (int k = 0; k < KINDS; k++) {
            records[k] = new float[16 * FLOATS];
        }
        if (s.density() <= 0) {
            return new Tile(tx, tz, new float[KINDS][0], null);
        }
        double perSquareMetre = s.density() / 10_000;
        int cells = (int) Math.ceil(TILE * Math.sqrt(perSquareMetre));
        double cell = TILE / cells;
        double keep = perSquareMetre * cell * cell;
        float[] box = null;
        for (int j = 0; j < cells; j++) {
            for (int i = 0; i < cells; i++) {
                long cx = tx * cells + i;
                long cz = tz * cells + j;
                long h = mix(mix(mix(seed) ^ cx) ^ cz);
                double u = unit(h, 0);
                if (u >= keep) {
                    continue;
                }
                double px = (cx + unit(h, 1)) * cell;
                double pz = (cz + unit(h, 2)) * cell;
                double ground = heights.heightAt(px, pz);
                if (!limits.allow(ground, gradient(heights, px, pz)) || u >= keep * field.density(px, pz, ground)) {
                    continue;
                }
                TreeKind kind = field.kind(px, pz, ground, unit(h, 6));
                double height = kind.scale * field.stature(px, pz, ground)
                        * (s.minHeight() + (s.maxHeight() - s.minHeight()) * unit(h, 3));
                int k = kind.ordinal();
                if ((counts[k] + 1) * FLOATS > records[k].length) {
                    records[k] = Arrays.copyOf(records[k], 2 * records[k].length);
                }
                // the foot from the tile's corner: under TILE metres, where a float keeps tenths of a millimetre
                double localX = px - tx * TILE;
                double localZ = pz - tz * TILE;
                float[] r = records[k];
                int o = counts[k]++ * FLOATS;
                r[o] = (float) localX;
                r[o + 1] = (float) ground;
                r[o + 2] = (float) localZ;
                r[o + 3] = (float) height;
                r[o + 4] = (float) (2 * Math.PI * unit(h, 4));
                r[o + 5] = (float) unit(h, 5);
                box = grow(box, localX, localZ, height * kind.reach, ground - TreeShape.SINK * height,
                        ground + height);
            }
        }
        for (int k = 0; k < KINDS; k++) {
            records[k] = Arrays.copyOf(records[k], counts[k] * FLOATS);
        }
        return new Tile(tx, tz, records, box);
    }

    /**
     * The tiles' plants in one layout, kind by kind, measured from the corner of the tile under (x, z); tiles without
     * plants are left out.
     */
    static Layout assemble(List<Tile> tiles, double x, double z) {
        double centreX = Math.floor(x / TILE) * TILE;
        double centreZ = Math.floor(z / TILE) * TILE;
        List<Tile> kept = tiles.stream().filter(t -> t.box() != null).toList();
        int total = 0;
        for (Tile t : kept) {
            for (float[] r : t.records()) {
                total += r.length;
            }
        }
        float[] records = new float[total];
        int[][] first = new int[KINDS][kept.size()];
        int[][] count = new int[KINDS][kept.size()];
        float[] boxes = new float[6 * (kept.size() + 1)];
        int at = 0;
        for (int k = 0; k < KINDS; k++) {
            for (int t = 0; t < kept.size(); t++) {
                Tile tile = kept.get(t);
                float[] r = tile.records()[k];
                System.arraycopy(r, 0, records, at, r.length);
                // the tile's corner from the centre: whole tiles, exact in double and in float
                moveFeet(records, at, r.length, FLOATS, tile.tx() * TILE - centreX, tile.tz() * TILE - centreZ);
                first[k][t] = at / FLOATS;
                count[k][t] = r.length / FLOATS;
                at += r.length;
            }
        }
        for (int t = 0; t < kept.size(); t++) {
            Tile tile = kept.get(t);
            System.arraycopy(tile.box(), 0, boxes, 6 * (t + 1), 6);
            moveFeet(boxes, 6 * (t + 1), 6, 3, tile.tx() * TILE - centreX, tile.tz() * TILE - centreZ);
        }
        return new Layout(records, first, count, bounds(boxes, kept.size()), centreX, centreZ);
    }

    /**
     * Adds (dx, dz) metres, in double, to the x and z of the points in {@code values[at .. at + length)}, one every
     * {@code stride} floats, x, y, z first: the records' feet ({@link #FLOATS}) or a box's corners (3).
     */
    private static void moveFeet(float[] values, int at, int length, int stride, double dx, double dz) {
        for (int o = at; o < at + length; o += stride) {
            values[o] = (float) (values[o] + dx);
            values[o + 2] = (float) (values[o + 2] + dz);
        }
    }

    /** The ground's gradient (rise over run) at (x, z), by central differences. */
    static double gradient(HeightField field, double x, double z) {
        double gx = (field.heightAt(x + PROBE, z) - field.heightAt(x - PROBE, z)) / (2 * PROBE);
        double gz = (field.heightAt(x, z + PROBE) - field.heightAt(x, z - PROBE)) / (2 * PROBE);
        return Math.sqrt(gx * gx + gz * gz);
    }

    /** A box (min xyz, max xyz), made or widened to hold a plant at (x, z) of this reach, from bottom to top. */
    private static float[] grow(float[] box, double x, double z, double reach, double bottom, double top) {
        if (box == null) {
            box = new float[] {Float.MAX_VALUE, Float.MAX_VALUE, Float.MAX_VALUE,
                -Float.MAX_VALUE, -Float.MAX_VALUE, -Float.MAX_VALUE};
        }
        box[0] = (float) Math.min(box[0], x - reach);
        box[1] = (float) Math.min(box[1], bottom);
        box[2] = (float) Math.min(box[2], z - reach);
        box[3] = (float) Math.max(box[3], x + reach);
        box[4] = (float) Math.max(box[4], top);
        box[5] = (float) Math.max(box[5], z + reach);
        return box;
    }

    /** A root holding every tile's box, and the tiles as its leaves; null when no plant stands. */
    private static BoundsTree bounds(float[] boxes, int tiles) {
        if (tiles == 0) {
            return null;
        }
        for (int c = 0; c < 3; c++) {
            boxes[c] = Float.MAX_VALUE;
            boxes[3 + c] = -Float.MAX_VALUE;
            for (int t = 1; t <= tiles; t++) {
                boxes[c] = Math.min(boxes[c], boxes[6 * t + c]);
                boxes[3 + c] = Math.max(boxes[3 + c], boxes[6 * t + 3 + c]);
            }
        }
        int[] firstChild = new int[tiles + 1];
        int[] childCount = new int[tiles + 1];
        firstChild[0] = 1;
        childCount[0] = tiles;
        return new BoundsTree(boxes, firstChild, childCount);
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

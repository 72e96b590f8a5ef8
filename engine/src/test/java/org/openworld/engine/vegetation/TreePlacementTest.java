package org.openworld.engine.vegetation;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.environment.SnowLine;
import org.openworld.engine.origin.RenderOrigin;

/**
 * Where the plants stand, without GL: the seed, the order tiles are placed in, the water, the snow, the slope, the
 * density field and the culling boxes.
 */
class TreePlacementTest {

    static final TreePlacement.Limits ANYWHERE = new TreePlacement.Limits(Double.NEGATIVE_INFINITY, null,
            VegetationSettings.DEFAULTS.maxGradient());
    /** A gentle slope rising 2 m per 100 m eastwards, 1.1°: from −20 m to 20 m across a 2 km disc. */
    static final HeightField RAMP = (x, z) -> 0.02 * x;

    static TreePlacement.Layout place(HeightField field, double x, double z, double radius, TreePlacement.Limits limits,
                                      int seed) {
        return TreePlacement.around(field, null, x, z, radius, VegetationSettings.DEFAULTS, limits, seed);
    }

    static float at(TreePlacement.Layout layout, int plant, int component) {
        return layout.records()[plant * TreePlacement.FLOATS + component];
    }

    /** The kind of the i-th plant: the layout holds every tile's plants of one kind before the next kind's. */
    static TreeKind kindOf(TreePlacement.Layout layout, int plant) {
        int end = 0;
        for (TreeKind kind : TreeKind.values()) {
            for (int c : layout.tileCount()[kind.ordinal()]) {
                end += c;
            }
            if (plant < end) {
                return kind;
            }
        }
        throw new IllegalArgumentException("plant " + plant + " of " + layout.count());
    }

    static Set<String> feet(TreePlacement.Layout layout, double minX) {
        Set<String> feet = new HashSet<>();
        float[] world = layout.worldRecords();
        for (int o = 0; o < world.length; o += TreePlacement.FLOATS) {
            if (world[o] > minX) {
                feet.add(world[o] + "," + world[o + 2]);
            }
        }
        return feet;
    }

    @Test
    void theSameSeedGrowsTheSamePlantsAndAnotherSeedOthers() {
        TreePlacement.Layout a = place(RAMP, 0, 0, 800, ANYWHERE, 7);
        TreePlacement.Layout b = place(RAMP, 0, 0, 800, ANYWHERE, 7);
        TreePlacement.Layout c = place(RAMP, 0, 0, 800, ANYWHERE, 8);
        assertTrue(a.count() > 100, "plants: " + a.count());
        assertArrayEquals(a.records(), b.records());
        Set<String> shared = feet(a, Double.NEGATIVE_INFINITY);
        shared.retainAll(feet(c, Double.NEGATIVE_INFINITY));
        assertTrue(shared.size() < a.count() / 20, "plants shared by two seeds: " + shared.size() + " of " + a.count());
    }

    @Test
    void aTilesPlantsDoNotDependOnTheOrderOrTheThreadTilesArePlacedOn() throws InterruptedException {
        PlacementField field = new PlacementField(RAMP, null, ANYWHERE, 3);
        List<long[]> tiles = TreePlacement.tilesAround(0, 0, 900);
        List<TreePlacement.Tile> inOrder = new ArrayList<>();
        for (long[] t : tiles) {
            inOrder.add(TreePlacement.tile(field, RAMP, t[0], t[1], VegetationSettings.DEFAULTS, ANYWHERE, 3));
        }
        // the same tiles, shuffled, on two threads at once, with a field made afresh (as a new placer would)
        List<Integer> order = new ArrayList<>();
        for (int i = 0; i < tiles.size(); i++) {
            order.add(i);
        }
        Collections.shuffle(order, new Random(1));
        TreePlacement.Tile[] shuffled = new TreePlacement.Tile[tiles.size()];
        PlacementField fresh = new PlacementField(RAMP, null, ANYWHERE, 3);
        Thread[] threads = new Thread[2];
        for (int n = 0; n < threads.length; n++) {
            int start = n;
            threads[n] = new Thread(() -> {
                for (int k = start; k < order.size(); k += 2) {
                    long[] t = tiles.get(order.get(k));
                    shuffled[order.get(k)] = TreePlacement.tile(fresh, RAMP, t[0], t[1], VegetationSettings.DEFAULTS,
                            ANYWHERE, 3);
                }
            });
            threads[n].start();
        }
        for (Thread t : threads) {
            t.join();
        }
        int plants = 0;
        for (int i = 0; i < tiles.size(); i++) {
            for (int k = 0; k < TreePlacement.KINDS; k++) {
                assertArrayEquals(inOrder.get(i).records()[k], shuffled[i].records()[k], "tile " + i + ", kind " + k);
                plants += inOrder.get(i).records()[k].length / TreePlacement.FLOATS;
            }
        }
        assertTrue(plants > 1000, "plants compared: " + plants);
    }

    @Test
    void aPlacerThatMovedGrowsTheSamePlantsWhereTheTwoDiscsOverlap() {
        TreePlacer placer = new TreePlacer(new TreePlacer.World(RAMP, null, VegetationSettings.DEFAULTS, ANYWHERE, 3));
        Set<String> here = feet(placer.around(0, 0, 600), Double.NEGATIVE_INFINITY);
        Set<String> moved = feet(placer.around(300, -170, 600), Double.NEGATIVE_INFINITY);
        Set<String> fresh = feet(place(RAMP, 300, -170, 600, ANYWHERE, 3), Double.NEGATIVE_INFINITY);
        assertEquals(fresh, moved, "tiles kept from before and tiles placed afresh make the same plants");
        Set<String> both = new HashSet<>(here);
        both.retainAll(moved);
        assertTrue(both.size() > 100, "plants in the overlap: " + both.size());
    }

    @Test
    void aFootTenThousandKilometresOutKeepsItsCentimetresOnTheGpu() {
        // 2442 tiles of 4096 m out on x, 1221 on z: a float there keeps whole metres, half a metre off at worst
        double farX = 2442 * 4096.0 + 1000;
        double farZ = 1221 * 4096.0 - 700;
        HeightField ramp = (x, z) -> 0.02 * (x - farX);
        TreePlacement.Layout layout = TreePlacement.around(ramp, null, farX, farZ, 600, VegetationSettings.DEFAULTS,
                ANYWHERE, 3);
        RenderOrigin origin = new RenderOrigin(RenderOrigin.DEFAULT_STEP);
        origin.follow(farX, farZ);
        float placedX = origin.relativeX(layout.centreX());
        float placedZ = origin.relativeZ(layout.centreZ());
        // the same tiles on their own: each foot from its tile's corner, a few hundred metres, exact to 0.02 mm
        PlacementField field = new PlacementField(ramp, null, ANYWHERE, 3);
        List<TreePlacement.Tile> tiles = new ArrayList<>();
        for (long[] t : TreePlacement.tilesAround(farX, farZ, 600)) {
            TreePlacement.Tile tile = TreePlacement.tile(field, ramp, t[0], t[1], VegetationSettings.DEFAULTS,
                    ANYWHERE, 3);
            if (tile.box() != null) {
                tiles.add(tile);
            }
        }
        assertEquals(tiles.size(), layout.tiles());
        double worst = 0;
        for (int k = 0; k < TreePlacement.KINDS; k++) {
            for (int t = 0; t < tiles.size(); t++) {
                float[] own = tiles.get(t).records()[k];
                for (int o = 0; o < own.length; o += TreePlacement.FLOATS) {
                    int r = (layout.tileFirst()[k][t] * TreePlacement.FLOATS) + o;
                    // the foot from the render origin as tree.vert adds it (float), against the exact one (double)
                    double exactX = tiles.get(t).tx() * TreePlacement.TILE + own[o] - origin.x();
                    double exactZ = tiles.get(t).tz() * TreePlacement.TILE + own[o + 2] - origin.z();
                    worst = Math.max(worst, Math.abs((layout.records()[r] + placedX) - exactX));
                    worst = Math.max(worst, Math.abs((layout.records()[r + 2] + placedZ) - exactZ));
                }
            }
        }
        System.out.println(layout.count() + " plants 10 000 km out, the worst foot " + worst + " m off");
        assertTrue(layout.count() > 100, "plants: " + layout.count());
        // a float a few kilometres from the origin rounds by 0.25 mm, twice (the record, then the sum): 1 cm is
        // forty times that, and fifty times below the half metre a float of the world's x loses here
        assertTrue(worst < 0.01, "the worst foot is " + worst + " m from where it stands");
    }

    @Test
    void noPlantStandsBelowTheWaterPlusTheShoreMarginOrAboveTheTreeLine() {
        // a 22° slope, from −400 m to 400 m across the disc; water at −5 m, the margin 2 m, snow from 200 m, certain
        // at 400 m: the tree line half-way, at 300 m, where snow is as likely as not
        HeightField hill = (x, z) -> 0.4 * x;
        SnowLine snow = new SnowLine(200, 400);
        TreePlacement.Limits limits = new TreePlacement.Limits(-5 + 2, snow, VegetationSettings.DEFAULTS.maxGradient());
        assertEquals(300, limits.highest(), 1e-9);
        TreePlacement.Layout kept = place(hill, 0, 0, 1000, limits, 1);
        assertTrue(kept.count() > 100, "plants between the water and the snow: " + kept.count());
        int inSnowFringe = 0;
        for (int i = 0; i < kept.count(); i++) {
            double y = at(kept, i, 1);
            assertEquals(hill.heightAt(at(kept, i, 0), at(kept, i, 2)), y, 1e-3, "the foot is on the ground");
            assertTrue(y >= -3 && y <= 300, "a foot at " + y + " m, outside −3 .. 300 m");
            assertTrue(snow.chanceAt(y) <= TreePlacement.Limits.TREELINE_CHANCE, "a foot where snow is likely");
            inSnowFringe += y > snow.start() ? 1 : 0;
        }
        // trees climb into the snow's fringe (the old rule stopped them at its start), thinning
        assertTrue(inSnowFringe > 0, "no plant above the snow's start");
    }

    @Test
    void theTreeLineStandsHigherOnSlopesFacingTheSun() {
        // two 29° slopes (gradient 0.55, within the 30° limit), one facing south (the sun, falling towards +z), one
        // north; the same snow on both
        TreePlacement.Limits limits = new TreePlacement.Limits(Double.NEGATIVE_INFINITY, new SnowLine(200, 400),
                VegetationSettings.DEFAULTS.maxGradient());
        double g = 0.55;
        HeightField sunny = (x, z) -> -g * z;
        HeightField shady = (x, z) -> g * z;
        PlacementField sun = new PlacementField(sunny, null, limits, 3);
        PlacementField shade = new PlacementField(shady, null, limits, 3);
        double line = limits.highest();
        double band = PlacementField.TREELINE_BAND;
        for (double h = line - band; h < line; h += 10) {
            // the same height on either slope: z = ∓h / g
            assertTrue(sun.treeline(0, -h / g, h) > shade.treeline(0, h / g, h), "at " + h + " m");
        }
        // half the band below the line a sunny slope keeps nearly its full forest (less the snow's patches), where a
        // shaded one has lost most of it: the bands start (1 ∓ ASPECT · 0.95) · 250 m below the line
        double half = line - band / 2;
        double snowless = 1 - limits.snowChance(half);
        assertTrue(sun.treeline(0, -half / g, half) / snowless > 0.9, "sunny: " + sun.treeline(0, -half / g, half));
        assertTrue(shade.treeline(0, half / g, half) / snowless < 0.4, "shaded: " + shade.treeline(0, half / g, half));
        // and the plants themselves: the top band's plants against those of a band as deep below both tree lines'
        // bands (the sunny slope is drier, so it grows fewer everywhere: the ratio compares like with like)
        double[] ratio = new double[2];
        for (int side = 0; side < 2; side++) {
            TreePlacement.Layout l = place(side == 0 ? sunny : shady, 0, 0, 1500, limits, 3);
            int top = 0;
            int below = 0;
            for (int i = 0; i < l.count(); i++) {
                double y = at(l, i, 1);
                top += y > line - band ? 1 : 0;
                below += y > line - 2.5 * band && y <= line - 1.5 * band ? 1 : 0;
            }
            assertTrue(below > 300, "plants below the tree line's band: " + below);
            ratio[side] = top / (double) below;
        }
        assertTrue(ratio[0] > 1.3 * ratio[1], "the top band's plants over those below: sunny " + ratio[0]
                + ", shaded " + ratio[1]);
    }

    @Test
    void broadleafTreesGrowLowConifersHighBushesAndShorterTreesAtTheTreeLine() {
        // a 6° ramp from −200 m to 200 m across the disc: the water's edge at −150 m, snow from 100 m, certain at
        // 300 m, so the tree line at 200 m; the plants sorted by the share of the way from the shore to the line
        HeightField ramp = (x, z) -> 0.1 * x;
        TreePlacement.Limits limits = new TreePlacement.Limits(-150, new SnowLine(100, 300), 1);
        TreePlacement.Layout layout = place(ramp, 0, 0, 2000, limits, 7);
        int zones = 5;
        int[][] counted = new int[zones][TreePlacement.KINDS];
        double[] treeHeight = new double[zones];
        for (int i = 0; i < layout.count(); i++) {
            double up = (at(layout, i, 1) + 150) / (limits.highest() + 150);
            int zone = Math.min(zones - 1, (int) (up * zones));
            TreeKind kind = kindOf(layout, i);
            counted[zone][kind.ordinal()]++;
            treeHeight[zone] += at(layout, i, 3) / kind.scale;
        }
        int conifer = TreeKind.CONIFER.ordinal();
        int broadleaf = TreeKind.BROADLEAF.ordinal();
        int bush = TreeKind.BUSH.ordinal();
        // below ZONE_LOW of the way the trees are broadleaf, above ZONE_HIGH conifers, but where the moisture moves
        // the zones (by ZONE_MOISTURE at most): a fifth of the trees either way is allowed for that
        double lowBroadleaf = counted[0][broadleaf] / (double) (counted[0][broadleaf] + counted[0][conifer]);
        double highConifer = counted[3][conifer] / (double) (counted[3][broadleaf] + counted[3][conifer]);
        assertTrue(lowBroadleaf > 0.8, "broadleaf share of the trees low down: " + lowBroadleaf);
        assertTrue(highConifer > 0.8, "conifer share of the trees high up: " + highConifer);
        // bushes take over at the tree line (KRUMMHOLZ), and the trees there are shorter (MIN_STATURE)
        double midBush = counted[2][bush] / (double) sum(counted[2]);
        double topBush = counted[4][bush] / (double) sum(counted[4]);
        assertTrue(topBush > midBush + 0.1, "bushes' share mid-slope " + midBush + ", at the tree line " + topBush);
        double midHeight = treeHeight[2] / sum(counted[2]);
        double topHeight = treeHeight[4] / sum(counted[4]);
        VegetationSettings s = VegetationSettings.DEFAULTS;
        assertEquals((s.minHeight() + s.maxHeight()) / 2, midHeight, 1, "mid-slope plants at full stature");
        assertTrue(topHeight < 0.85 * midHeight, "heights mid-slope " + midHeight + ", at the tree line "
                + topHeight);
        // and the forest thins: fewer plants in the top fifth than in the middle one
        assertTrue(sum(counted[4]) < 0.6 * sum(counted[2]), "plants mid-slope " + sum(counted[2])
                + ", at the tree line " + sum(counted[4]));
    }

    static int sum(int[] values) {
        int total = 0;
        for (int v : values) {
            total += v;
        }
        return total;
    }

    @Test
    void noPlantStandsOnGroundSteeperThanTheLimit() {
        // flat west of x = 0; east of it a 40° slope (gradient 0.84), steeper than the default 30° (0.58)
        HeightField cliff = (x, z) -> Math.max(0, x) * Math.tan(Math.toRadians(40));
        TreePlacement.Layout layout = place(cliff, 0, 0, 500, ANYWHERE, 5);
        assertTrue(layout.count() > 100, "plants on the flat half: " + layout.count());
        for (int i = 0; i < layout.count(); i++) {
            assertTrue(at(layout, i, 0) < TreePlacement.PROBE, "a plant on the slope at x = " + at(layout, i, 0));
        }
        // with a 45° limit the slope grows what flat ground there would: the field does not see the tilt (no water,
        // no snow, a plane has no hollows), except within its probe of the fold at x = 0
        TreePlacement.Limits steep = new TreePlacement.Limits(Double.NEGATIVE_INFINITY, null,
                Math.tan(Math.toRadians(45)));
        double clear = PlacementField.PROBE + TreePlacement.PROBE;
        Set<String> climbing = feet(place(cliff, 0, 0, 500, steep, 5), clear);
        assertTrue(climbing.size() > 30, "plants on the slope: " + climbing.size());
        assertEquals(feet(place(HeightField.FLAT, 0, 0, 500, ANYWHERE, 5), clear), climbing);
    }

    @Test
    void theDensityFollowsTheField() {
        // on flat ground with no water and no snow the field is the forest patches times the moisture stand-in's
        // base; the disc's ground is sorted into four classes by the field's value, from a 10 m grid
        double radius = 1500;
        int seed = 11;
        VegetationSettings s = VegetationSettings.DEFAULTS;
        PlacementField field = new PlacementField(HeightField.FLAT, null, ANYWHERE, seed);
        double cellArea = 100;
        double[] area = new double[4];
        double[] expected = new double[4];
        for (double x = -radius; x < radius; x += 10) {
            for (double z = -radius; z < radius; z += 10) {
                if (Math.hypot(x + 5, z + 5) < radius) {
                    double f = field.density(x + 5, z + 5, 0);
                    int c = Math.min(3, (int) (f * 4));
                    area[c] += cellArea;
                    expected[c] += s.density() / 10_000 * cellArea * f;
                }
            }
        }
        int[] counted = new int[4];
        TreePlacement.Layout layout = TreePlacement.around(HeightField.FLAT, null, 0, 0, radius, s, ANYWHERE, seed);
        for (int i = 0; i < layout.count(); i++) {
            if (Math.hypot(at(layout, i, 0), at(layout, i, 2)) < radius) {
                counted[Math.min(3, (int) (field.density(at(layout, i, 0), at(layout, i, 2), 0) * 4))]++;
            }
        }
        double disc = Math.PI * radius * radius;
        // forests and clearings: both the sparsest and the densest class cover a good share of the ground
        assertTrue(area[0] > 0.15 * disc && area[3] > 0.05 * disc, "field classes' areas: " + List.of(area[0],
                area[1], area[2], area[3]));
        for (int c = 0; c < 4; c++) {
            // a sum of independent cells' draws: a binomial spread of at most √expected, allowed four of them; the
            // 10 m grid's estimate of each class's integral adds its edge cells' error, a few per cent of it
            double allowed = 4 * Math.sqrt(expected[c]) + 0.05 * expected[c];
            assertEquals(expected[c], counted[c], allowed, "plants where the field is " + c / 4.0 + " to "
                    + (c + 1) / 4.0);
        }
        assertTrue(counted[3] / area[3] > 5 * counted[0] / area[0], "forest against open: " + counted[3] / area[3]
                + " and " + counted[0] / area[0] + " a square metre");
    }

    @Test
    void thinsOutTowardsTheTreeLine() {
        // the field's tree line without water, on a ramp facing neither the sun nor away (the aspect is 0): snow
        // from 0 m, certain at 24 m, the line at 12 m; nothing there, the full density 250 m below it, half between
        TreePlacement.Limits limits = new TreePlacement.Limits(Double.NEGATIVE_INFINITY, new SnowLine(0, 24), 1);
        PlacementField field = new PlacementField(RAMP, null, limits, 1);
        assertEquals(0, field.treeline(600, 0, 12), 1e-9);
        assertEquals(1, field.treeline(-11900, 0, 12 - PlacementField.TREELINE_BAND), 1e-9);
        assertEquals(0.5, field.treeline(-5650, 0, 12 - PlacementField.TREELINE_BAND / 2), 1e-9);
        // with water, over the top quarter of the heights from the shore (2 m) to the line (402 m): 302 to 402 m,
        // times the chance of no snow above its start (352 m; certain at 452 m)
        PlacementField shore = new PlacementField(RAMP, null, new TreePlacement.Limits(2, new SnowLine(352, 452), 1),
                1);
        assertEquals(0, shore.treeline(20100, 0, 402), 1e-9);
        assertEquals(1, shore.treeline(15100, 0, 302), 1e-9);
        assertEquals(0.5, shore.treeline(17600, 0, 352), 1e-9);
        assertEquals(0.75 * (1 - PlacementField.smoothstep(302, 402, 377)), shore.treeline(18850, 0, 377), 1e-9);
        assertEquals(PlacementField.MIN_STATURE, shore.stature(20100, 0, 402), 1e-9);
    }

    @Test
    void heightsTurnsAndTintsLieInTheirRanges() {
        TreePlacement.Layout layout = place(RAMP, 0, 0, 500, ANYWHERE, 2);
        VegetationSettings s = VegetationSettings.DEFAULTS;
        Set<TreeKind> kinds = new HashSet<>();
        for (int i = 0; i < layout.count(); i++) {
            TreeKind kind = kindOf(layout, i);
            kinds.add(kind);
            double h = at(layout, i, 3) / kind.scale;
            assertTrue(h >= s.minHeight() - 1e-3 && h <= s.maxHeight() + 1e-3, "height " + h);
            assertTrue(at(layout, i, 4) >= 0 && at(layout, i, 4) < 2 * Math.PI, "turn");
            assertTrue(at(layout, i, 5) >= 0 && at(layout, i, 5) < 1, "tint");
        }
        assertEquals(Set.of(TreeKind.values()), kinds, "every kind grows on the ramp");
    }

    @Test
    void everyTileBoxHoldsItsPlantsWholeAndTheRootHoldsEveryTile() {
        TreePlacement.Layout layout = place(RAMP, 100, 100, 700, ANYWHERE, 4);
        float[] boxes = layout.bounds().boxes();
        assertEquals(layout.tiles(), layout.bounds().childCount(0));
        int plants = 0;
        for (TreeKind kind : TreeKind.values()) {
            for (int t = 0; t < layout.tiles(); t++) {
                int node = layout.bounds().firstChild(0) + t;
                assertEquals(plants, layout.tileFirst()[kind.ordinal()][t], "tiles follow one another");
                for (int i = plants; i < plants + layout.tileCount()[kind.ordinal()][t]; i++) {
                    double h = at(layout, i, 3);
                    double reach = kind.reach * h - 1e-3; // less a float's rounding at a few hundred metres
                    assertTrue(at(layout, i, 0) - reach >= boxes[6 * node]
                            && at(layout, i, 0) + reach <= boxes[6 * node + 3]);
                    assertTrue(at(layout, i, 2) - reach >= boxes[6 * node + 2]
                            && at(layout, i, 2) + reach <= boxes[6 * node + 5]);
                    assertTrue(at(layout, i, 1) - TreeShape.SINK * h >= boxes[6 * node + 1] - 1e-3);
                    assertTrue(at(layout, i, 1) + h <= boxes[6 * node + 4] + 1e-3);
                }
                for (int c = 0; c < 3; c++) {
                    assertTrue(boxes[c] <= boxes[6 * node + c] && boxes[3 + c] >= boxes[6 * node + 3 + c], "root");
                }
                plants += layout.tileCount()[kind.ordinal()][t];
            }
        }
        assertEquals(layout.count(), plants);
        assertTrue(layout.tiles() > 0);
    }

    @Test
    void everyShapeIsWithinItsKindsReachAndTheSimplifiedOnesAreCheaper() {
        for (TreeKind kind : TreeKind.values()) {
            TreeShape.Geometry near = TreeShape.of(kind, false);
            TreeShape.Geometry far = TreeShape.of(kind, true);
            for (TreeShape.Geometry shape : List.of(near, far)) {
                float[] v = shape.vertices();
                double widest = 0;
                double top = 0;
                for (int i = 0; i < v.length; i += TreeShape.FLOATS) {
                    widest = Math.max(widest, Math.hypot(v[i], v[i + 2]));
                    top = Math.max(top, v[i + 1]);
                }
                // the shader widens a plant by up to 1.15 (tree.vert, WIDTH_LOW + WIDTH_SPREAD) and leans it
                // downwind by at most 0.06 x 1.33 of its height at the top (MAX_LEAN times the swing)
                assertTrue(widest * 1.15 + 0.08 <= kind.reach, kind + ": widest " + (widest * 1.15 + 0.08));
                assertTrue(top <= 1.0 + 1e-6, kind + ": top " + top);
            }
            assertTrue(far.triangleCount() * 4 <= near.triangleCount(), kind + ": " + far.triangleCount()
                    + " triangles far, " + near.triangleCount() + " near");
        }
    }
}

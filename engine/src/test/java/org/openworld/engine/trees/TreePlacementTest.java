package org.openworld.engine.trees;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.openworld.engine.core.HeightField;

/** Where the trees stand, without GL: the seed, the water, the snow, the slope, the density and the culling boxes. */
class TreePlacementTest {

    static final TreePlacement.Limits ANYWHERE = new TreePlacement.Limits(Double.NEGATIVE_INFINITY,
            Double.POSITIVE_INFINITY, TreeSettings.DEFAULTS.maxGradient());
    /** A gentle slope rising 2 m per 100 m eastwards, 1.1°: from −20 m to 20 m across a 2 km disc. */
    static final HeightField RAMP = (x, z) -> 0.02 * x;

    static TreeSettings settings(double density) {
        TreeSettings d = TreeSettings.DEFAULTS;
        return new TreeSettings(density, d.maxSlope(), d.minHeight(), d.maxHeight(), d.viewDistance(), d.shoreMargin());
    }

    static TreePlacement.Layout place(HeightField field, double x, double z, double radius, TreePlacement.Limits limits,
                                      int seed) {
        return TreePlacement.around(field, x, z, radius, TreeSettings.DEFAULTS, limits, seed);
    }

    static float at(TreePlacement.Layout layout, int tree, int component) {
        return layout.worldRecords()[tree * TreePlacement.FLOATS + component];
    }

    static Set<String> feet(TreePlacement.Layout layout) {
        Set<String> feet = new HashSet<>();
        for (int i = 0; i < layout.count(); i++) {
            feet.add(at(layout, i, 0) + "," + at(layout, i, 2));
        }
        return feet;
    }

    /** The feet to the millimetre, x and z in one key. */
    static Set<Long> feetToTheMillimetre(TreePlacement.Layout layout) {
        Set<Long> feet = new HashSet<>();
        for (int i = 0; i < layout.count(); i++) {
            feet.add(millimetres(at(layout, i, 0), at(layout, i, 2), 0, 0));
        }
        return feet;
    }

    private static long millimetres(float x, float z, int dx, int dz) {
        return (Math.round(x * 1000.0) + dx) * 100_000_000L + Math.round(z * 1000.0) + dz;
    }

    /**
     * Whether a foot lies within a millimetre of (x, z): the records hold the feet from the disc's centre, so two
     * discs round the same foot to floats differently, by a float's step at a few hundred metres (60 µm), which may
     * tip its millimetre either way.
     */
    static boolean hasFootAt(Set<Long> feet, float x, float z) {
        for (int dz = -1; dz <= 1; dz++) {
            for (int dx = -1; dx <= 1; dx++) {
                if (feet.contains(millimetres(x, z, dx, dz))) {
                    return true;
                }
            }
        }
        return false;
    }

    @Test
    void theSameSeedGrowsTheSameTreesAndAnotherSeedOthers() {
        TreePlacement.Layout a = place(RAMP, 0, 0, 800, ANYWHERE, 7);
        TreePlacement.Layout b = place(RAMP, 0, 0, 800, ANYWHERE, 7);
        TreePlacement.Layout c = place(RAMP, 0, 0, 800, ANYWHERE, 8);
        assertTrue(a.count() > 100, "trees: " + a.count());
        assertArrayEquals(a.records(), b.records());
        Set<String> shared = feet(a);
        shared.retainAll(feet(c));
        assertTrue(shared.size() < a.count() / 20, "trees shared by two seeds: " + shared.size() + " of " + a.count());
    }

    @Test
    void aTreeDependsOnItsPlaceAloneNotOnWhereTheDiscWasCentred() {
        TreePlacement.Layout here = place(RAMP, 0, 0, 600, ANYWHERE, 3);
        TreePlacement.Layout moved = place(RAMP, 300, -170, 600, ANYWHERE, 3);
        Set<Long> movedFeet = feetToTheMillimetre(moved);
        int inBoth = 0;
        for (int i = 0; i < here.count(); i++) {
            float x = at(here, i, 0);
            float z = at(here, i, 2);
            if (Math.hypot(x - 300, z + 170) < 599) {
                inBoth++;
                assertTrue(hasFootAt(movedFeet, x, z),
                        "a rebuilt disc grows the same trees where the two overlap: none at " + x + ", " + z);
            }
        }
        assertTrue(inBoth > 100, "trees in the overlap: " + inBoth);
    }

    @Test
    void noTreeStandsBelowTheWaterPlusTheShoreMarginOrAboveTheSnowLine() {
        TreePlacement.Limits limits = new TreePlacement.Limits(-5 + 2, 12, TreeSettings.DEFAULTS.maxGradient());
        TreePlacement.Layout all = place(RAMP, 0, 0, 1000, ANYWHERE, 1);
        TreePlacement.Layout kept = place(RAMP, 0, 0, 1000, limits, 1);
        double lowest = Double.POSITIVE_INFINITY;
        double highest = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < kept.count(); i++) {
            double y = at(kept, i, 1);
            assertEquals(RAMP.heightAt(at(kept, i, 0), at(kept, i, 2)), y, 1e-3, "the foot is on the ground");
            lowest = Math.min(lowest, y);
            highest = Math.max(highest, y);
        }
        assertTrue(lowest >= -3 && lowest < -2.5, "the lowest foot, just above water + margin: " + lowest);
        assertTrue(highest <= 12 && highest > 11.5, "the highest foot, just below the snow line: " + highest);
        // the band from −3 to 12 m is 750 m of the 2 km ramp: the share of the disc between x = −150 and 600 m
        double band = bandShare(-150, 600, 1000);
        assertEquals(band, (double) kept.count() / all.count(), 0.03, "share of the trees kept");
    }

    /** The share of a disc of radius r round the origin lying between x = a and x = b. */
    static double bandShare(double a, double b, double r) {
        return (segment(b, r) - segment(a, r)) / (Math.PI * r * r);
    }

    /** The area of the disc west of x = t. */
    static double segment(double t, double r) {
        return r * r * Math.acos(-t / r) + t * Math.sqrt(r * r - t * t);
    }

    @Test
    void noTreeStandsOnGroundSteeperThanTheLimit() {
        // flat west of x = 0; east of it a 40° slope (gradient 0.84), steeper than the default 30° (0.58)
        HeightField cliff = (x, z) -> Math.max(0, x) * Math.tan(Math.toRadians(40));
        TreePlacement.Layout layout = place(cliff, 0, 0, 500, ANYWHERE, 5);
        assertTrue(layout.count() > 100, "trees on the flat half: " + layout.count());
        for (int i = 0; i < layout.count(); i++) {
            assertTrue(at(layout, i, 0) < TreePlacement.PROBE, "a tree on the slope at x = " + at(layout, i, 0));
        }
        TreePlacement.Limits steep = new TreePlacement.Limits(Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY,
                Math.tan(Math.toRadians(45)));
        TreePlacement.Layout climbing = place(cliff, 0, 0, 500, steep, 5);
        assertEquals(2 * layout.count(), climbing.count(), 0.1 * layout.count(),
                "with a 45° limit, trees grow on the slope too, as densely as on the flat");
    }

    @Test
    void theCountIsTheDensityTimesTheArea() {
        for (double density : new double[] {3, 30, 250}) {
            double radius = 1200;
            TreePlacement.Layout layout = TreePlacement.around(HeightField.FLAT, 40, -70, radius, settings(density),
                    ANYWHERE, 11);
            double expected = density * Math.PI * radius * radius / 10_000;
            // a binomial count: its spread is at most √expected; allow four of them
            assertEquals(expected, layout.count(), 4 * Math.sqrt(expected), "trees at " + density + " per hectare");
        }
    }

    @Test
    void heightsTurnsAndTintsLieInTheirRanges() {
        TreePlacement.Layout layout = place(RAMP, 0, 0, 500, ANYWHERE, 2);
        TreeSettings s = TreeSettings.DEFAULTS;
        for (int i = 0; i < layout.count(); i++) {
            assertTrue(at(layout, i, 3) >= s.minHeight() && at(layout, i, 3) <= s.maxHeight(), "height");
            assertTrue(at(layout, i, 4) >= 0 && at(layout, i, 4) < 2 * Math.PI, "turn");
            assertTrue(at(layout, i, 5) >= 0 && at(layout, i, 5) < 1, "tint");
        }
    }

    @Test
    void everyTileBoxHoldsItsTreesWholeAndTheRootHoldsEveryTile() {
        TreePlacement.Layout layout = place(RAMP, 100, 100, 700, ANYWHERE, 4);
        float[] boxes = layout.bounds().boxes();
        assertEquals(layout.tiles(), layout.bounds().childCount(0));
        int trees = 0;
        for (int t = 0; t < layout.tiles(); t++) {
            int node = layout.bounds().firstChild(0) + t;
            assertEquals(trees, layout.tileFirst()[t], "tiles follow one another");
            for (int i = trees; i < trees + layout.tileCount()[t]; i++) {
                double h = at(layout, i, 3);
                double reach = TreePlacement.REACH * h - 1e-3; // less a float's rounding at a few hundred metres
                assertTrue(at(layout, i, 0) - reach >= boxes[6 * node] && at(layout, i, 0) + reach <= boxes[6 * node + 3]);
                assertTrue(at(layout, i, 2) - reach >= boxes[6 * node + 2] && at(layout, i, 2) + reach <= boxes[6 * node + 5]);
                assertTrue(at(layout, i, 1) - TreeShape.SINK * h >= boxes[6 * node + 1] - 1e-3);
                assertTrue(at(layout, i, 1) + h <= boxes[6 * node + 4] + 1e-3);
            }
            for (int c = 0; c < 3; c++) {
                assertTrue(boxes[c] <= boxes[6 * node + c] && boxes[3 + c] >= boxes[6 * node + 3 + c], "root");
            }
            trees += layout.tileCount()[t];
        }
        assertEquals(layout.count(), trees);
        assertFalse(layout.tiles() == 0);
    }

    @Test
    void theShapesWidestReachIsWithinTheBoxesReach() {
        float[] v = TreeShape.coneStack().vertices();
        double widest = 0;
        for (int i = 0; i < v.length; i += TreeShape.FLOATS) {
            widest = Math.max(widest, Math.hypot(v[i], v[i + 2]));
        }
        // the shader widens a tree by up to 1.15 (tree.vert, WIDTH_LOW + WIDTH_SPREAD)
        assertTrue(widest * 1.15 <= TreePlacement.REACH, "widest " + widest * 1.15);
    }
}

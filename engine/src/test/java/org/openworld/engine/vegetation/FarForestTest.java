package org.openworld.engine.vegetation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.openworld.engine.core.HeightField;

/** The far forests' map, without GL: it follows the plants the same rules place, and any window agrees with another. */
class FarForestTest {

    /** A gentle slope, 2 m per 100 m eastwards: the water (at −5 m, plus the shore margin) west of x = −350 m. */
    static final HeightField RAMP = TreePlacementTest.RAMP;
    static final TreePlacement.Limits SHORE = new TreePlacement.Limits(-5 + VegetationSettings.DEFAULTS.shoreMargin(),
            null, VegetationSettings.DEFAULTS.maxGradient());
    /** Crowns from above, units of the height squared: any values do, both sides of each check use the same. */
    static final double[] TOP_AREA = {0.2, 0.4, 0.9};
    static final int SEED = 5;

    static TreePlacer.World world() {
        return new TreePlacer.World(RAMP, null, VegetationSettings.DEFAULTS, SHORE, SEED);
    }

    static int alpha(FarForest.Window w, int i, int j) {
        return w.rgba()[(j * FarForest.SIZE + i) * 4 + 3] & 0xFF;
    }

    /**
     * Over the texels within 1 km of the viewer, the mean share of ground hidden agrees with the one the plants
     * actually placed there hide (each plant's crown from above, the same areas, over the texel's area, through the
     * same 1 − exp(−·)); the texels on the water hold none. The bound: the texels sample the field at their centres
     * while the plants sample it all over the texel, and the plants' count in a texel is random (about 60 at the
     * default density, ±13 %); over the ~190 texels compared the means agree within a tenth.
     */
    @Test
    void theCoverFollowsThePlantsTheSameRulesPlace() {
        FarForest.Window w = FarForest.around(world(), new PlacementField(RAMP, null, SHORE, SEED), TOP_AREA, 0, 0);
        TreePlacement.Layout plants = TreePlacement.around(RAMP, null, 0, 0, 1100, VegetationSettings.DEFAULTS, SHORE,
                SEED);
        double texel = FarForest.EXTENT / FarForest.SIZE;
        int n = (int) Math.ceil(1000 / texel);
        double[][] hidden = new double[2 * n][2 * n];
        float[] world = plants.worldRecords();
        for (int p = 0; p < plants.count(); p++) {
            int o = p * TreePlacement.FLOATS;
            int ti = (int) Math.floor(world[o] / texel) + n;
            int tj = (int) Math.floor(world[o + 2] / texel) + n;
            if (ti >= 0 && tj >= 0 && ti < 2 * n && tj < 2 * n) {
                TreeKind kind = TreePlacementTest.kindOf(plants, p);
                double h = world[o + 3] / kind.scale; // the tree height the kind's share was taken of
                hidden[ti][tj] += TOP_AREA[kind.ordinal()] * kind.scale * kind.scale * h * h / (texel * texel);
            }
        }
        double fromMap = 0;
        double fromPlants = 0;
        int texels = 0;
        for (int a = 0; a < 2 * n; a++) {
            for (int b = 0; b < 2 * n; b++) {
                int i = Math.floorMod(a - n, FarForest.SIZE);
                int j = Math.floorMod(b - n, FarForest.SIZE);
                double x = (a - n + 0.5) * texel;
                if (Math.hypot(x, (b - n + 0.5) * texel) > 1000) {
                    continue;
                }
                if (x + texel / 2 < -350) { // wholly on the water
                    assertEquals(0, alpha(w, i, j), "cover on the water at x = " + x);
                    assertEquals(0, hidden[a][b], "plants on the water at x = " + x);
                }
                fromMap += alpha(w, i, j) / 255.0;
                fromPlants += 1 - Math.exp(-hidden[a][b]);
                texels++;
            }
        }
        assertTrue(texels > 150, "texels compared: " + texels);
        assertTrue(fromPlants / texels > 0.1, "the plants hide " + fromPlants / texels + " of the ground");
        assertEquals(fromPlants / texels, fromMap / texels, 0.1 * fromPlants / texels,
                "the share of the ground hidden, by the map and by the plants");
    }

    /** Two windows made around different points hold the same cover for every point both hold: no order matters. */
    @Test
    void windowsAroundDifferentPointsAgreeWhereTheyOverlap() {
        PlacementField field = new PlacementField(RAMP, null, SHORE, SEED);
        FarForest.Window a = FarForest.around(world(), field, TOP_AREA, 0, 0);
        FarForest.Window b = FarForest.around(world(), field, TOP_AREA, 3000, -2500);
        double texel = FarForest.EXTENT / FarForest.SIZE;
        int same = 0;
        for (int j = 0; j < FarForest.SIZE; j++) {
            for (int i = 0; i < FarForest.SIZE; i++) {
                double ax = FarForest.nearest((i + 0.5) * texel, a.x());
                double az = FarForest.nearest((j + 0.5) * texel, a.z());
                if (ax == FarForest.nearest((i + 0.5) * texel, b.x())
                        && az == FarForest.nearest((j + 0.5) * texel, b.z())) {
                    for (int c = 0; c < 4; c++) {
                        int o = (j * FarForest.SIZE + i) * 4 + c;
                        assertEquals(a.rgba()[o], b.rgba()[o], "texel (" + i + ", " + j + ") channel " + c);
                    }
                    same++;
                }
            }
        }
        assertTrue(same > FarForest.SIZE * FarForest.SIZE / 2, "texels both windows hold: " + same);
        // and a point is held where it lies: the nearest congruent point is within half the extent
        assertEquals(100.0, FarForest.nearest(100 + 3 * FarForest.EXTENT, 0), 1e-9);
        assertEquals(-100.0, FarForest.nearest(FarForest.EXTENT - 100, 0), 1e-9);
    }
}

package org.openworld.engine.grass;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.environment.SnowLine;

/** The grass's field and its draws, without GL: the rules, and that both stand on the world's grid. */
class GrassFieldTest {

    static final GrassSettings S = GrassSettings.DEFAULTS;
    /** Water at 0 m (grass from 0.3 m), snow from 100 m, certain at 200 m, the default 30° limit. */
    static final GrassField.Rules RULES = new GrassField.Rules(GrassSystem.SHORE, new SnowLine(100, 200),
            S.maxGradient());
    static final GrassRuns.Frustum EVERYWHERE = (x0, y0, z0, x1, y1, z1) -> true;

    /** The share at the sample nearest the world's (x, z). */
    static float shareAt(GrassField f, double x, double z) {
        return f.share((int) (Math.round(x / GrassField.SPACING) - f.firstX()),
                (int) (Math.round(z / GrassField.SPACING) - f.firstZ()));
    }

    @Test
    void noGrassUnderWaterOnSteepGroundOrAboveTheSnowLineAndLessWhereSnowIsLikely() {
        // east of x = 0 a ramp of 45° (rock); west of it, flat strips along z: under water, a meadow, the snow's
        // patchy band, full snow
        HeightField land = (x, z) -> x > 0 ? x : z < -20 ? -5 : z < 0 ? 10 : z < 20 ? 150 : 250;
        GrassField f = GrassField.around(-30, 0, 40, land, null, RULES);
        assertEquals(0, shareAt(f, -30, -30), "under the water");
        assertEquals(1, shareAt(f, -30, -10), "on the meadow");
        // 150 m: half-way from the snow's start to its full line, so half the grass
        assertEquals(0.5, shareAt(f, -30, 10), 1e-6, "in the snow's patchy band");
        assertEquals(0, shareAt(f, -30, 30), "above the full snow line");
        assertEquals(0, shareAt(f, 10, -10), "on the 45° ramp");
        // a 25° ramp is under the 30° limit: grass (a sample two away from the kink, whose slope the central
        // difference mixes)
        HeightField gentle = (x, z) -> Math.tan(Math.toRadians(25)) * Math.max(0, x) + 10;
        assertEquals(1, shareAt(GrassField.around(0, 0, 40, gentle, null, RULES), 5, 0), "on a 25° slope");
    }

    @Test
    void aSampleIsTheSameWhicheverSquareTheViewersMovesMake() {
        HeightField land = (x, z) -> 20 + 15 * Math.sin(x / 17) * Math.cos(z / 23);
        GrassField a = GrassField.around(3.3, -7.1, 40, land, null, RULES);
        GrassField b = GrassField.around(15.8, 4.6, 40, land, null, RULES);
        int shared = 0;
        for (int j = 0; j < a.size(); j++) {
            for (int i = 0; i < a.size(); i++) {
                int bi = (int) (a.firstX() + i - b.firstX());
                int bj = (int) (a.firstZ() + j - b.firstZ());
                if (bi >= 0 && bj >= 0 && bi < b.size() && bj < b.size()) {
                    shared++;
                    assertEquals(a.height(i, j), b.height(bi, bj), "height at sample " + i + ", " + j);
                    assertEquals(a.share(i, j), b.share(bi, bj), "share at sample " + i + ", " + j);
                }
            }
        }
        // the squares reach 50 m either side; moved 12.5 m east and 11.7 m south they share most samples
        assertTrue(shared > a.size() * a.size() / 2, "samples shared: " + shared);
    }

    /** The world's cells a plan draws, as "x,z", failing on a cell drawn twice. */
    static Set<String> cells(List<GrassRuns.Run> runs) {
        Set<String> cells = new HashSet<>();
        for (GrassRuns.Run run : runs) {
            for (int i = 0; i < run.instances(); i++) {
                String cell = (run.cellX() + i % run.wide()) + "," + (run.cellZ() + i / run.wide());
                assertTrue(cells.add(cell), "cell " + cell + " drawn twice");
            }
        }
        return cells;
    }

    @Test
    void theTuftsStayInTheirWorldCellsAsTheViewerMoves() {
        HeightField flat = (x, z) -> 10;
        double cell = S.cell();
        double d = S.distance();
        GrassField field = GrassField.around(0, 0, d, flat, null, RULES);
        Set<String> before = cells(GrassRuns.plan(0.11, 0.07, d, cell, S.height(), field, EVERYWHERE));
        // moved by a fraction of a cell: the instances are the same world cells, not shifted with the eye
        Set<String> after = cells(GrassRuns.plan(0.11 + 0.37 * cell, 0.07 - 0.61 * cell, d, cell, S.height(), field,
                EVERYWHERE));
        int checked = 0;
        for (long cz = (long) Math.floor(-d / cell); cz <= d / cell; cz++) {
            for (long cx = (long) Math.floor(-d / cell); cx <= d / cell; cx++) {
                // every cell within the distance of both eyes (less a cell, for its corners) is drawn by both
                if (Math.hypot((cx + 0.5) * cell, (cz + 0.5) * cell) < d - 2 * cell) {
                    String c = cx + "," + cz;
                    assertTrue(before.contains(c) && after.contains(c), "cell " + c + " drawn before and after");
                    checked++;
                }
            }
        }
        assertTrue(checked > 1000, "cells checked: " + checked);
        // nothing in view, or no grass on the ground: no draw
        assertTrue(GrassRuns.plan(0, 0, d, cell, S.height(), field, (x0, y0, z0, x1, y1, z1) -> false).isEmpty());
        GrassField bare = GrassField.around(0, 0, d, (x, z) -> -3, null, RULES);
        assertTrue(GrassRuns.plan(0, 0, d, cell, S.height(), bare, EVERYWHERE).isEmpty(), "grass under the water");
    }

    @Test
    void theCellIndicesFitTheShadersIntegersAtTheEdgeOfTheWorld() {
        // the shader hashes a cell's index as a 32-bit int: at the farthest camera and the densest grass (the
        // smallest cell) the indices must still fit
        GrassSettings densest = new GrassSettings(200, S.distance(), S.height(), S.maxSlope());
        double far = CameraPose.MAX_COORDINATE_M;
        GrassField field = GrassField.around(far, -far, S.distance(), (x, z) -> 10, null, RULES);
        List<GrassRuns.Run> runs = GrassRuns.plan(far, -far, S.distance(), densest.cell(), S.height(), field,
                EVERYWHERE);
        assertTrue(!runs.isEmpty(), "runs at the edge");
        for (GrassRuns.Run run : runs) {
            assertTrue(run.cellX() + run.wide() < Integer.MAX_VALUE && run.cellZ() - GrassRuns.BLOCK
                    > Integer.MIN_VALUE, "cell " + run.cellX() + ", " + run.cellZ() + " beyond an int");
        }
    }
}

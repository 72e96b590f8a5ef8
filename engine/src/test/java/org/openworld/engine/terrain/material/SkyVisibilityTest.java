package org.openworld.engine.terrain.material;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.function.DoubleBinaryOperator;
import org.junit.jupiter.api.Test;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.HeightPyramid;

/**
 * {@link SkyVisibility} against what it must give in closed form: the whole sky on open ground and on a plain slope
 * (the ground's own tilt hides nothing the normal does not), and at the foot of a cliff the share the cliff hides.
 */
class SkyVisibilityTest {

    static final int N = 512;
    static final double SPACING = 16;

    /** A map of N² samples, not periodic (the edges clamp), with heights f(x, z) in metres. */
    static HeightPyramid world(DoubleBinaryOperator f) {
        float[] h = new float[N * N];
        for (int row = 0; row < N; row++) {
            for (int col = 0; col < N; col++) {
                h[row * N + col] = (float) f.applyAsDouble((col - N / 2.0) * SPACING, (row - N / 2.0) * SPACING);
            }
        }
        return HeightPyramid.build(new HeightMap(N, SPACING, h, false));
    }

    @Test
    void openGroundSeesTheWholeSky() {
        SkyVisibility v = SkyVisibility.of(world((x, z) -> 100), 0);
        assertEquals(1.0, v.visibleAt(0, 0), 1e-9);
        assertEquals(1.0, v.visibleAt((3 - N / 2.0) * SPACING, (N / 2.0 - 5) * SPACING), 1e-9);
    }

    @Test
    void aPlainSlopeHidesNothingBeyondItsOwnTilt() {
        // 30° rising towards +x: measured from the ground itself, the uphill horizon is 30° high, which the sky
        // light of the tilted normal already leaves out
        double tan = Math.tan(Math.toRadians(30));
        SkyVisibility v = SkyVisibility.of(world((x, z) -> tan * x), 0);
        for (double x : new double[] {-500, 0, 400}) {
            // the visibility is stored in 8 bits: one level below 1 is the rounding of "all the sky"
            assertTrue(v.visibleAt(x, 0) >= 254 / 255.0, "on the slope at x = " + x + ": "
                    + v.visibleAt(x, 0));
        }
        // and not because it ignores the ground: from the flat ground at the slope's foot the slope hides, along
        // each azimuth φ towards it, the sky below its elevation there, atan(tan 30° · cos φ)
        SkyVisibility kink = SkyVisibility.of(world((x, z) -> tan * Math.max(x, 0)), 0);
        double expected = 0;
        for (int m = 0; m < HorizonSearch.DIRECTIONS; m++) {
            double c = Math.cos(Math.atan(tan * Math.max(Math.cos(2 * Math.PI * m / HorizonSearch.DIRECTIONS), 0)));
            expected += c * c / HorizonSearch.DIRECTIONS;
        }
        // 0.02, 0.06 and 0.03: the horizon is searched over a height grid (16 m samples here) in a finite set of steps,
        // so an elevation is found to about a sample's angle; the cliff's foot, nearest the edge, errs most; the 8-bit
        // storage adds 0.004
        assertEquals(expected, kink.visibleAt(-32, 0), 0.02, "at the foot of the slope");
        assertTrue(expected < 0.95, "the slope hides a share: " + expected);
    }

    @Test
    void theFootOfACliffSeesTheSkyTheCliffLeaves() {
        double height = 400;
        SkyVisibility v = SkyVisibility.of(world((x, z) -> x >= 0 ? height : 0), 0);
        for (double d : new double[] {-96, -192, -400, -800}) {
            // closed form for the same azimuths: towards the cliff (cos φ > 0) its top stands at atan(H cos φ / d)
            double expected = 0;
            for (int m = 0; m < HorizonSearch.DIRECTIONS; m++) {
                double c = Math.cos(2 * Math.PI * m / HorizonSearch.DIRECTIONS);
                double rise = c > 1e-9 ? Math.cos(Math.atan(height * c / -d)) : 1;
                expected += rise * rise / HorizonSearch.DIRECTIONS;
            }
            double measured = v.visibleAt(d, 0);
            assertEquals(expected, measured, 0.06, d + " m from the cliff");
        }
        assertEquals(1.0, v.visibleAt(-2500, 0), 0.03, "far from the cliff");
        // the closed form gives about 0.6 at 96 m from a 400 m cliff: 0.8 leaves the 0.06 band and more
        assertTrue(v.visibleAt(-96, 0) < 0.8, "at its foot: " + v.visibleAt(-96, 0));
    }

    @Test
    void theShareWithoutTrigonometryIsTheCosineSquaredOfTheRise() {
        for (double p = -3; p <= 3; p += 0.25) {
            for (double q = -3; q <= 3; q += 0.25) {
                double rise = Math.atan(p) - Math.atan(q);
                double c = rise > 0 ? Math.cos(Math.min(rise, Math.PI / 2)) : 1;
                assertEquals(c * c, SkyVisibility.visibleShare(p, q), 1e-12, "horizon " + p + ", plane " + q);
            }
        }
    }

    @Test
    void theSearchGrowsFromOneSampleToTheReach() {
        for (double d : new double[] {1, 2, 8, 256}) {
            double[] r = HorizonSearch.distances(d);
            assertEquals(d, r[0], 0, "the first distance is one sample");
            for (int j = 1; j < r.length; j++) {
                assertEquals(HorizonSearch.STEP_GROWTH, r[j] / r[j - 1], 1e-12);
            }
            assertTrue(r[r.length - 1] >= HorizonSearch.REACH_METRES, "the last reaches " + r[r.length - 1]);
            assertTrue(r.length == 1 || r[r.length - 2] < HorizonSearch.REACH_METRES, "one step beyond at most");
        }
        assertEquals(0, HorizonSearch.distances(2 * HorizonSearch.REACH_METRES).length, "beyond the reach: none");
    }

    @Test
    void eachDistanceReadsTheCoarsestLevelAQuarterOfItApart() {
        int count = 8;
        for (int from = 0; from < count; from++) {
            for (double r : HorizonSearch.distances(Math.scalb(2.0, from))) {
                int k = HorizonSearch.levelAt(r, from, count, level -> Math.scalb(2.0, level));
                assertTrue(k >= from && k < count, "level " + k);
                assertTrue(k == from || Math.scalb(2.0, k) <= r / 4, r + " m reads level " + k);
                assertTrue(k == count - 1 || Math.scalb(2.0, k + 1) > r / 4, r + " m could read level " + (k + 1));
            }
        }
    }
}

package org.openworld.engine.minimap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.openworld.engine.core.HeightField;

/** The minimap's picture without GL: the hillshade, where the world lands on the map, when it is built again. */
class ReliefMapTest {
    // Tolerances here: doubles: hillshade and texture coordinates are exact expressions, equal to round-off (1e-9,
    // 1e-12)

    static final double RANGE = 4000;
    /** Rolling ground, 40 m hills 700 m apart: a field whose every texel differs. */
    static final HeightField HILLS = (x, z) -> 40 * Math.sin(x / 110) * Math.cos(z / 130);

    @Test
    void aSlopeFacingTheLightIsBrighterThanFlatGroundAndOneFacingAwayIsDark() {
        // rising 1 in 1.41 towards the south-east: the normal points at the light, 45 degrees up in the north-west
        double facing = ReliefMap.hillshade(Math.sqrt(0.5), Math.sqrt(0.5));
        double flat = ReliefMap.hillshade(0, 0);
        double away = ReliefMap.hillshade(-2, -2);
        // doubles: hillshade and texture coordinates are exact expressions, equal to round-off
        assertEquals(1, facing, 1e-9);
        assertTrue(facing > flat && flat > away, facing + " > " + flat + " > " + away);
        assertEquals(0, away, "a slope turned from the light gets none");
        // a slope facing north-east is lit from the side: between the two
        double side = ReliefMap.hillshade(-0.5, 0.5);
        assertTrue(side < facing && side > away);
    }

    @Test
    void flatGroundGetsTheSineOfTheLightsAltitudeAndTheLandColourUnderIt() {
        assertEquals(Math.sin(Math.toRadians(ReliefMap.LIGHT_ALTITUDE)), ReliefMap.hillshade(0, 0), 1e-12);
        ReliefMap map = ReliefMap.build((x, z) -> 120, 0, 0, RANGE, Double.NEGATIVE_INFINITY);
        double light = ReliefMap.AMBIENT + (1 - ReliefMap.AMBIENT) * Math.sqrt(0.5);
        for (int c = 0; c < 3; c++) {
            int expected = (int) Math.round(255 * ReliefMap.LAND[c] * light);
            assertEquals(expected, map.channel(0, 0, c));
            assertEquals(expected, map.channel(ReliefMap.TEXELS - 1, ReliefMap.TEXELS / 3, c));
        }
    }

    @Test
    void northOfTheCameraIsTheFirstRowsAndEastTheLastColumns() {
        double x = 1234;
        double z = -567;
        // a lake 1 km north of the camera, dry land everywhere else
        HeightField lakeToTheNorth = (px, pz) -> Math.hypot(px - x, pz - (z - 1000)) < 300 ? -20 : 50;
        ReliefMap map = ReliefMap.build(lakeToTheNorth, x, z, RANGE, 0);
        assertTrue(map.t(z - 1000) < map.t(z) && map.t(z) < map.t(z + 1000), "t runs south");
        assertTrue(map.s(x - 1000) < map.s(x) && map.s(x) < map.s(x + 1000), "s runs east");
        double texel = 1.0 / ReliefMap.TEXELS;
        assertEquals(0.5, map.s(x), texel, "the camera is within a texel of the centre");
        assertEquals(0.5, map.t(z), texel);
        assertTrue(isWater(map, map.s(x), map.t(z - 1000)), "the lake, in the northern rows");
        assertFalse(isWater(map, map.s(x), map.t(z + 1000)), "dry land to the south");
        assertFalse(isWater(map, map.s(x + 1000), map.t(z - 1000)), "dry land to the north-east");
    }

    @Test
    void mapsBuiltAtNearbyCamerasSampleTheSamePointsSoThePictureDoesNotSwim() {
        ReliefMap a = ReliefMap.build(HILLS, 100, 200, RANGE, Double.NEGATIVE_INFINITY);
        double spacing = ReliefMap.SPAN_PER_RANGE * RANGE / ReliefMap.TEXELS;
        // the second camera is 10 texels east and 4 south, and a little off the grid
        ReliefMap b = ReliefMap.build(HILLS, 100 + 10 * spacing + 0.3, 200 + 4 * spacing - 0.2, RANGE,
                Double.NEGATIVE_INFINITY);
        for (int j = 0; j < ReliefMap.TEXELS - 4; j += 37) {
            for (int i = 0; i < ReliefMap.TEXELS - 10; i += 41) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(a.channel(i + 10, j + 4, c), b.channel(i, j, c), "texel " + i + ", " + j);
                }
            }
        }
        assertEquals(a.s(777), b.s(777) + 10.0 / ReliefMap.TEXELS, 1e-9, "the same point, 10 texels west");
    }

    @Test
    void theMapIsBuiltAgainWhenTheCameraMovedAQuarterOfTheRangeOrWhatItShowsChanged() {
        ReliefMap map = ReliefMap.build(HILLS, 0, 0, RANGE, 0);
        double quarter = ReliefMap.REBUILD_SHARE * RANGE;
        assertTrue(map.covers(HILLS, 0, 0, RANGE, 0));
        assertTrue(map.covers(HILLS, quarter - 1, -(quarter - 1), RANGE, 0), "just inside, diagonally");
        assertFalse(map.covers(HILLS, quarter + 1, 0, RANGE, 0), "east");
        assertFalse(map.covers(HILLS, 0, -(quarter + 1), RANGE, 0), "north");
        assertFalse(map.covers(HILLS, 0, 0, 2 * RANGE, 0), "another range");
        assertFalse(map.covers(HILLS, 0, 0, RANGE, 5), "another water level");
        assertFalse(map.covers((x, z) -> 0, 0, 0, RANGE, 0), "another world");
    }

    @Test
    void whereverTheMapStillServesTheCameraTheRangeAroundItLiesOnTheMap() {
        ReliefMap map = ReliefMap.build(HILLS, 0, 0, RANGE, 0);
        double quarter = ReliefMap.REBUILD_SHARE * RANGE;
        for (double x : new double[] {-quarter, 0, quarter}) {
            for (double z : new double[] {-quarter, 0, quarter}) {
                assertTrue(map.covers(HILLS, x, z, RANGE, 0));
                // the minimap's edges, half the range from the camera, within the texture
                assertTrue(map.s(x - RANGE / 2) >= 0 && map.s(x + RANGE / 2) <= 1, "x " + x);
                assertTrue(map.t(z - RANGE / 2) >= 0 && map.t(z + RANGE / 2) <= 1, "z " + z);
                assertEquals(map.s(x + RANGE / 2) - map.s(x - RANGE / 2), map.shownShare(), 1e-9);
            }
        }
    }

    /** Whether the texel nearest texture coordinates (s, t) has the water's colour. */
    static boolean isWater(ReliefMap map, double s, double t) {
        int i = (int) (s * ReliefMap.TEXELS);
        int j = (int) (t * ReliefMap.TEXELS);
        for (int c = 0; c < 3; c++) {
            if (map.channel(i, j, c) != (int) Math.round(255 * ReliefMap.WATER[c])) {
                return false;
            }
        }
        return true;
    }
}

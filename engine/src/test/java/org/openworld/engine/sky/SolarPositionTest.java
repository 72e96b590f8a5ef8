package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/** Solar position (no GL): directions in docs/design.md's axes, X east, Y up, Z south. */
class SolarPositionTest {
    // Tolerances here: float directions (24-bit mantissa): 1e-5 on unit vectors; elevations in degrees (asin of a
    // float) to 1e-3; a search over hours in double to 1e-9. Bands such as x > 0.5 (30° off the meridian) say where the
    // sun is, with margin

    /** The default observer: mid-northern latitude in early summer. */
    static final double LATITUDE = SkySettings.DEFAULTS.latitude();
    static final double DECLINATION = SkySettings.DEFAULTS.declination();

    static Vector3f sunAt(double hours) {
        return SolarPosition.direction(hours, LATITUDE, DECLINATION);
    }

    static double elevation(Vector3f toSun) {
        return Math.toDegrees(Math.asin(toSun.y));
    }

    @Test
    void directionIsAUnitVector() {
        for (double h = 0; h < 24; h += 1.5) {
            // float vectors (24-bit mantissa): lengths and components to 1e-5, elevations (asin, in degrees) to 1e-3
            assertEquals(1, sunAt(h).length(), 1e-5, "at " + h + " h");
        }
    }

    @Test
    void sunRisesInTheEastCulminatesInTheSouthAndSetsInTheWest() {
        Vector3f morning = sunAt(8);
        Vector3f noon = sunAt(12);
        Vector3f evening = sunAt(16);

        // x > 0.5: more than 30° towards the east from the meridian, true for any sun 3 h or more from noon
        assertTrue(morning.x > 0.5 && morning.y > 0, "morning sun east and up: " + morning);
        assertTrue(noon.z > 0 && Math.abs(noon.x) < 1e-5, "noon sun due south: " + noon);
        assertTrue(evening.x < -0.5 && evening.y > 0, "evening sun west and up: " + evening);
        // symmetric about noon
        assertEquals(morning.y, evening.y, 1e-5);
        assertEquals(-morning.x, evening.x, 1e-5);
    }

    @Test
    void sunIsHighestAtNoonAtTheExpectedElevation() {
        double best = -1;
        double bestElevation = -90;
        for (double h = 0; h < 24; h += 0.25) {
            double e = elevation(sunAt(h));
            if (e > bestElevation) {
                bestElevation = e;
                best = h;
            }
        }
        assertEquals(12, best, 1e-9);
        // At noon the sun stands 90° − latitude + declination above the southern horizon.
        assertEquals(90 - LATITUDE + DECLINATION, bestElevation, 1e-3);
    }

    @Test
    void sunIsBelowTheHorizonAtMidnight() {
        Vector3f midnight = sunAt(0);
        assertTrue(midnight.y < 0, midnight.toString());
        assertEquals(-(90 - LATITUDE - DECLINATION), elevation(midnight), 1e-3);
    }

    @Test
    void hoursAtElevationInvertsTheDirection() {
        for (double e : new double[] {-6, -4, 0, 1, 10, 30}) {
            double morning = SolarPosition.hoursAtElevation(e, true, LATITUDE, DECLINATION);
            double evening = SolarPosition.hoursAtElevation(e, false, LATITUDE, DECLINATION);
            assertEquals(e, elevation(sunAt(morning)), 1e-3, "morning at " + e + "°");
            assertEquals(e, elevation(sunAt(evening)), 1e-3, "evening at " + e + "°");
            assertTrue(morning < 12 && evening > 12);
            assertTrue(sunAt(morning).x > 0 && sunAt(evening).x < 0, "east in the morning, west in the evening");
        }
    }

    @Test
    void elevationsTheSunNeverReachesAreAnError() {
        double noon = 90 - LATITUDE + DECLINATION;
        assertThrows(IllegalArgumentException.class,
                () -> SolarPosition.hoursAtElevation(noon + 1, true, LATITUDE, DECLINATION));
    }
}

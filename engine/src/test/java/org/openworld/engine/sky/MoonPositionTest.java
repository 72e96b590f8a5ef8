package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Matrix3f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/** The moon's place and phase and the stars' sphere (no GL), against facts of the real sky. */
class MoonPositionTest {
    // Tolerances here: float directions (24-bit mantissa) through a few rotations: 1e-5 on unit vectors, angles and
    // determinants; elevations in degrees (asin of a float) to 1e-3; exact doubles (the lit fraction) to 1e-12

    static final double LATITUDE = SkySettings.DEFAULTS.latitude();
    static final double DECLINATION = SkySettings.DEFAULTS.declination();
    static final double FULL = MoonPosition.SYNODIC_DAYS / 2;

    static Vector3f moon(double hours, double age) {
        return MoonPosition.direction(hours, LATITUDE, DECLINATION, age);
    }

    static Vector3f sun(double hours) {
        return SolarPosition.direction(hours, LATITUDE, DECLINATION);
    }

    @Test
    void theNewMoonStandsWithTheSunAndTheFullMoonOppositeIt() {
        for (double h = 0; h < 24; h += 2.5) {
            // float directions: 1e-5 radians of rounding
            assertEquals(0, moon(h, 0).angle(sun(h)), 1e-5, "new moon at " + h + " h");
            // angles of float vectors (24-bit mantissa): 1e-5 rad is a few float roundings through the rotations;
            // elevations in degrees to 1e-3
            assertEquals(Math.PI, moon(h, FULL).angle(sun(h)), 1e-5, "full moon at " + h + " h");
        }
    }

    @Test
    void theMoonStandsItsElongationFromTheSun() {
        // both on the ecliptic, so the angle between them is the difference of their longitudes, the elongation
        for (double age = 1; age < MoonPosition.SYNODIC_DAYS; age += 3.7) {
            double psi = MoonPosition.elongation(age);
            double expected = psi <= Math.PI ? psi : 2 * Math.PI - psi;
            assertEquals(expected, moon(20, age).angle(sun(20)), 1e-5, "age " + age + " d");
        }
    }

    @Test
    void theFullMoonOfSummerRunsLowAtMidnight() {
        // opposite the sun, at declination -10 degrees: due south at midnight, 90 - 46 - 10 = 34 degrees up
        Vector3f midnight = moon(0, FULL);
        assertEquals(34, Math.toDegrees(Math.asin(midnight.y)), 1e-3, "elevation");
        assertEquals(0, midnight.x, 1e-5, "due south: no east component");
        assertTrue(midnight.z > 0, "south");
    }

    @Test
    void theEveningCrescentStandsAboveTheSunsetInTheWest() {
        Vector3f crescent = moon(19.75, 3);
        // x < -0.5: more than 30° of azimuth towards the west, well clear of due south; the sun has set 3 days ×
        // 12.2°/day ≈ 37° away
        assertTrue(crescent.x < -0.5 && crescent.y > 0, "three days old, after sunset: west and up, " + crescent);
    }

    @Test
    void phaseAndLightFollowTheMagnitudeLaw() {
        // 1e-12 for exact values of (1 - cos φ) / 2 in double (ε 2.2e-16)
        assertEquals(0, MoonPosition.litFraction(0), 1e-12);
        assertEquals(1, MoonPosition.litFraction(FULL), 1e-12);
        assertEquals(0.5, MoonPosition.litFraction(FULL / 2), 1e-12);
        // the full moon: magnitude -12.73 against the sun's -26.74, 14.01 magnitudes: 2.49e-6 of the sunlight
        assertEquals(2.49e-6, MoonPosition.irradiance(FULL), 0.01e-6);
        // the quarter moon gives about a tenth of the full moon's light, not half (the surge at opposition): Allen's
        // law gives 0.089
        double quarter = MoonPosition.irradiance(FULL / 2) / MoonPosition.irradiance(FULL);
        // Allen's 0.089 ± about 20 %: the law is an empirical fit, the band only has to tell it from the 0.5 of a plain
        // lit fraction
        assertTrue(quarter > 0.07 && quarter < 0.11, "quarter against full " + quarter);
        assertTrue(MoonPosition.irradiance(1) < MoonPosition.irradiance(3), "a growing crescent brightens");
    }

    @Test
    void theStarsSphereIsARotationThatCarriesTheSunAndThePole() {
        for (double h = 0; h < 24; h += 3.5) {
            Matrix3f toLocal = MoonPosition.equatorialToLocal(h, LATITUDE, DECLINATION);
            assertEquals(1, toLocal.determinant(), 1e-5, "a rotation, not a reflection");
            // the sun's own equatorial direction lands where SolarPosition puts it
            double lambda = MoonPosition.sunLongitude(DECLINATION);
            double ra = MoonPosition.rightAscension(lambda);
            double dec = Math.toRadians(DECLINATION);
            Vector3f sunEq = new Vector3f((float) (Math.cos(dec) * Math.cos(ra)), (float) (Math.cos(dec) * Math.sin(ra)),
                    (float) Math.sin(dec));
            assertEquals(0, toLocal.transform(sunEq).angle(sun(h)), 1e-5, "the sun at " + h + " h");
            // the celestial pole stands due north at the latitude's elevation, whatever the hour
            Vector3f pole = toLocal.transform(new Vector3f(0, 0, 1));
            assertEquals(LATITUDE, Math.toDegrees(Math.asin(pole.y)), 1e-3, "the pole's elevation at " + h + " h");
            assertEquals(0, pole.x, 1e-5, "the pole due north");
        }
    }
}

package org.openworld.engine.environment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.openworld.engine.core.World;
import org.openworld.engine.settings.Settings;

/** Solar position and sunlight colour (no GL): directions in DESIGN.md's axes, X east, Y up, Z south. */
class DaylightSystemTest {

    /** The default observer: mid-northern latitude in early summer. */
    static final double LATITUDE = DaylightSystem.DaylightSettings.DEFAULTS.latitude();
    static final double DECLINATION = DaylightSystem.DaylightSettings.DEFAULTS.declination();

    static Vector3f sunAt(double hours) {
        return DaylightSystem.sunDirection(hours, LATITUDE, DECLINATION);
    }

    static double elevation(Vector3f toSun) {
        return Math.toDegrees(Math.asin(toSun.y));
    }

    @Test
    void directionIsAUnitVector() {
        for (double h = 0; h < 24; h += 1.5) {
            assertEquals(1, sunAt(h).length(), 1e-5, "at " + h + " h");
        }
    }

    @Test
    void sunRisesInTheEastCulminatesInTheSouthAndSetsInTheWest() {
        Vector3f morning = sunAt(8);
        Vector3f noon = sunAt(12);
        Vector3f evening = sunAt(16);

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
    void lowSunIsRedderThanHighSun() {
        Vector3f low = DaylightSystem.transmittance(5);
        Vector3f high = DaylightSystem.transmittance(60);

        assertTrue(low.x / low.z > high.x / high.z, "red/blue at 5°: " + low + ", at 60°: " + high);
        assertTrue(high.x > low.x && high.z > low.z, "less light through more air");
        // every channel is reddened relative to the next: R > G > B at any elevation above the horizon
        for (Vector3f t : List.of(low, high)) {
            assertTrue(t.x > t.y && t.y > t.z, t.toString());
        }
    }

    @Test
    void noSunlightWellBelowTheHorizon() {
        assertEquals(new Vector3f(), DaylightSystem.transmittance(-5));
        assertEquals(new Vector3f(), DaylightSystem.transmittance(-30));
        assertTrue(DaylightSystem.transmittance(0.5).length() > 0);
    }

    @Test
    void updatePublishesSunAndFogFromTheWorldsClock() {
        World world = new World();
        world.setResource(new Settings(List.of(DaylightSystem.SETTINGS)));
        DaylightSystem daylight = new DaylightSystem();

        world.setResource(new TimeOfDay(10, 0));
        daylight.update(world, 1 / 60.0);
        Sun day = world.resource(Sun.class);
        Fog dayFog = world.resource(Fog.class);

        world.setResource(new TimeOfDay(23, 0));
        daylight.update(world, 1 / 60.0);
        Sun night = world.resource(Sun.class);
        Fog nightFog = world.resource(Fog.class);

        assertEquals(sunAt(10).x, day.direction().x(), 1e-6);
        assertEquals(sunAt(10).y, day.direction().y(), 1e-6);
        assertTrue(day.color().x() > 0.5, day.color().toString());
        assertEquals(0, night.color().length(), 0, "no direct light at night");
        assertTrue(night.ambient().length() < day.ambient().length() / 5, night.ambient() + " vs " + day.ambient());
        assertTrue(nightFog.color().length() < dayFog.color().length() / 5);
        assertEquals(DaylightSystem.DaylightSettings.DEFAULTS.fogDensity(), dayFog.density(), 1e-9);
    }

    @Test
    void latitudeSettingMovesTheNoonSun() {
        World world = new World();
        Settings settings = new Settings(List.of(DaylightSystem.SETTINGS));
        world.setResource(settings);
        world.setResource(new TimeOfDay(12, 0));
        DaylightSystem daylight = new DaylightSystem();

        settings.set("daylight.latitude", "-40");
        settings.set("daylight.declination", "-20");
        daylight.update(world, 0);

        // southern hemisphere in its summer: the noon sun stands in the north (z < 0)
        Sun sun = world.resource(Sun.class);
        assertTrue(sun.direction().z() < 0, sun.direction().toString());
        assertEquals(90 - 40 + 20, sun.elevationDegrees(), 1e-3);
    }
}

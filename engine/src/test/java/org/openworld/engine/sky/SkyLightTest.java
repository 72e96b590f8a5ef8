package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.openworld.engine.sky.SkyColours.luminance;

import org.joml.Vector3d;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

class SkyLightTest {

    private static final double ALTITUDE = 200;
    private static AtmosphereTables tables;

    @BeforeAll
    static void build() {
        tables = AtmosphereTables.build(AtmosphereSettings.DEFAULTS);
    }

    @Test
    void noonSunIsNearlyWhite() {
        SkyLight light = light(60);
        Vector3d sun = light.sun();
        assertTrue(luminance(sun) > 0.7 && luminance(sun) < 1, "luminance " + luminance(sun));
        assertTrue(sun.get(sun.maxComponent()) < 1.25 * sun.get(sun.minComponent()), "white-ish: " + sun);
        Vector3d ambient = light.ambient();
        assertTrue(ambient.z > ambient.x, "the sky's light is bluer than the sun's: " + ambient);
        assertTrue(luminance(ambient) > 0.05 && luminance(ambient) < luminance(sun), "ambient " + ambient);
    }

    @Test
    void sunsetSunIsRed() {
        Vector3d sun = light(1).sun();
        assertTrue(sun.x > sun.y && sun.y > sun.z, sun.toString());
    }

    @Test
    void nightHasNoSunAndAlmostNoSky() {
        SkyLight light = light(-10);
        assertEquals(0, light.sun().length());
        assertTrue(luminance(light.ambient()) < 1e-4, light.ambient().toString());
    }

    @Test
    void theSunFadesAsItsDiscSets() {
        double horizon = -Math.acos(Atmosphere.BOTTOM_RADIUS / SkyIntegrator.eyeRadius(ALTITUDE));
        double radius = Math.toRadians(SkyLight.SUN_ANGULAR_RADIUS_DEG);
        double above = luminance(light(Math.toDegrees(horizon + 0.5 * radius)).sun());
        double half = luminance(light(Math.toDegrees(horizon)).sun());
        double below = luminance(light(Math.toDegrees(horizon - 1.01 * radius)).sun());
        assertTrue(above > half && half > 0, above + " > " + half + " > 0");
        assertEquals(0, below);
        assertEquals(0.5, SkyLight.discFractionAbove(0), 1e-12);
        assertEquals(1, SkyLight.discFractionAbove(1), 1e-12);
        assertEquals(0, SkyLight.discFractionAbove(-1), 1e-12);
    }

    private static SkyLight light(double sunDegrees) {
        double sun = Math.toRadians(sunDegrees);
        return SkyLight.of(tables, SkyView.build(tables, sun, ALTITUDE), sun, ALTITUDE);
    }
}

package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.openworld.engine.sky.SkyColours.luminance;

import org.joml.Vector3d;
import org.joml.Vector3f;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.openworld.engine.environment.SkyIrradiance;
import org.openworld.engine.environment.Sun;

class SkyLightTest {

    /** No moon above the horizon and a black night sky: the sun's and the day sky's light alone. */
    static final NightLight NO_NIGHT = new NightLight(new Vector3f(0, -1, 0), new Vector3d(), new Vector3d(),
            new Vector3d());

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
        // at 60° elevation the clear air's transmittance is about 0.8 of the top of the atmosphere's (air mass 1.15);
        // ±0.1 either side
        assertTrue(luminance(sun) > 0.7 && luminance(sun) < 1, "luminance " + luminance(sun));
        // white-ish: the channels within 25 %, a colour a viewer still calls white in daylight (a low sun reddens far
        // past it)
        assertTrue(sun.get(sun.maxComponent()) < 1.25 * sun.get(sun.minComponent()), "white-ish: " + sun);
        Vector3d ambient = light.ambient();
        assertTrue(ambient.z > ambient.x, "the sky's light is bluer than the sun's: " + ambient);
        // a clear sky's diffuse light is 10–20 % of the direct sun's; 0.05 catches a black sky
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
        // 1e-4 of noon: below one 8-bit sRGB level (3e-4 of linear light) at noon's exposure
        assertTrue(luminance(light.ambient()) < 1e-4, light.ambient().toString());
    }

    @Test
    void theSunFadesAsItsDiscSets() {
        double horizon = -Math.acos(Atmosphere.BOTTOM_RADIUS / SkyIntegrator.eyeRadius(ALTITUDE));
        double radius = Math.toRadians(Sun.ANGULAR_RADIUS_DEG);
        double above = luminance(light(Math.toDegrees(horizon + 0.5 * radius)).sun());
        double half = luminance(light(Math.toDegrees(horizon)).sun());
        double below = luminance(light(Math.toDegrees(horizon - 1.01 * radius)).sun());
        assertTrue(above > half && half > 0, above + " > " + half + " > 0");
        assertEquals(0, below);
        assertEquals(0.5, SkyLight.discFractionAbove(0), 1e-12);
        assertEquals(1, SkyLight.discFractionAbove(1), 1e-12);
        assertEquals(0, SkyLight.discFractionAbove(-1), 1e-12);
    }

    /**
     * The harmonics of the sky: facing up, the ambient light (the same table, another quadrature); facing the sun,
     * brighter than facing away (the sky is brightest around the sun), whichever way the sun stands; facing down,
     * the ground's bounce light (albedo × the light on level ground), the sky's own share there being only the
     * harmonics' ringing.
     */
    @Test
    void theSkysIrradianceIsTheAmbientUpwardsFollowsTheSunAndAddsTheGroundBelow() {
        double elevation = Math.toRadians(40);
        SkyView view = SkyView.build(tables, elevation, ALTITUDE);
        SkyLight light = SkyLight.of(tables, view, elevation, ALTITUDE);
        float c = (float) Math.cos(elevation);
        float s = (float) Math.sin(elevation);
        SkyIrradiance east = SkyLight.irradiance(view, light, new Vector3f(c, s, 0), 0.3, NO_NIGHT);
        SkyIrradiance north = SkyLight.irradiance(view, light, new Vector3f(0, s, -c), 0.3, NO_NIGHT);
        double up = luminance(east.irradiance(new Vector3d(0, 1, 0), new Vector3d()));
        // 6 %: the same sky integrated two ways (the ambient from the tables, the irradiance from its low-order
        // harmonics); the band covers the harmonics' smoothing
        assertEquals(luminance(light.ambient()), up, 0.06 * up, "facing up");
        SkyIrradiance skyOnly = SkyLight.irradiance(view, light, new Vector3f(c, s, 0), 0, NO_NIGHT);
        double towards = luminance(skyOnly.irradiance(new Vector3d(1, 0, 0), new Vector3d()));
        double away = luminance(skyOnly.irradiance(new Vector3d(-1, 0, 0), new Vector3d()));
        // the sun's aureole (forward Mie scattering) brightens the sky on the sun's side: 15 % stands clear of the
        // harmonics' 6 % error above
        assertTrue(towards > 1.15 * away, "sky light on a wall facing the sun " + towards + ", facing away " + away);
        towards = luminance(east.irradiance(new Vector3d(1, 0, 0), new Vector3d()));
        assertEquals(towards, luminance(north.irradiance(new Vector3d(0, 0, -1), new Vector3d())), 1e-3 * towards,
                "the sun in the north: the same light on a wall facing north");
        double ground = 0.3 * (luminance(light.sun()) * s + luminance(light.ambient()));
        // 10 %: the ground is a uniform albedo-0.3 hemisphere below, and the low-order harmonics smooth the step at the
        // horizon between it and the sky (1e-3 above where only the azimuth turns)
        assertEquals(ground, luminance(east.irradiance(new Vector3d(0, -1, 0), new Vector3d())), 0.1 * ground,
                "facing down");
    }

    private static SkyLight light(double sunDegrees) {
        double sun = Math.toRadians(sunDegrees);
        return SkyLight.of(tables, SkyView.build(tables, sun, ALTITUDE), sun, ALTITUDE);
    }
}

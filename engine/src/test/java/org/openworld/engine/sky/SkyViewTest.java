package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.openworld.engine.sky.SkyColours.luminance;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.Map;

import org.joml.Vector3d;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.openworld.engine.sky.AtmosphereSettings.Component;
import org.openworld.engine.sky.AtmosphereSettings.Scattering;

class SkyViewTest {
    // Tolerances here: doubles: the texture mapping and its inverse agree to a few ε (2.2e-16) of angles up to 2π, so
    // 1e-12 to 1e-15; sky bands are explained beside them

    private static final double ALTITUDE = 100;
    private static AtmosphereTables multiple;
    private static AtmosphereTables single;

    @BeforeAll
    static void build() {
        multiple = SkyColours.tables(Scattering.MULTIPLE, Component.BOTH);
        single = SkyColours.tables(Scattering.SINGLE, Component.BOTH);
    }

    @Test
    void noonZenithIsBlue() {
        for (AtmosphereTables t : new AtmosphereTables[] {multiple, single}) {
            Vector3d zenith = SkyView.build(t, Math.toRadians(60), ALTITUDE).sample(0, Math.PI / 2, new Vector3d());
            assertTrue(zenith.z > zenith.y && zenith.y > zenith.x, t.settings().scattering() + ": " + zenith);
        }
    }

    @Test
    void sunsetHorizonTowardTheSunIsRed() {
        for (AtmosphereTables t : new AtmosphereTables[] {multiple, single}) {
            Vector3d horizon = SkyView.build(t, Math.toRadians(1), ALTITUDE)
                    .sample(0, Math.toRadians(0.5), new Vector3d());
            assertTrue(horizon.x > horizon.y && horizon.y > horizon.z, t.settings().scattering() + ": " + horizon);
        }
    }

    @Test
    void multipleScatteringLightsTheTwilightZenith() {
        double sun = Math.toRadians(-4);
        double withMultiple = luminance(SkyView.build(multiple, sun, ALTITUDE).sample(0, Math.PI / 2, new Vector3d()));
        double singleOnly = luminance(SkyView.build(single, sun, ALTITUDE).sample(0, Math.PI / 2, new Vector3d()));
        assertTrue(singleOnly > 0, "the high air is still lit at -4 degrees");
        // at -4° the zenith's high air sees little direct sun: light scattered more than once must add a large share
        // (half again), not a rounding
        assertTrue(withMultiple >= 1.5 * singleOnly, withMultiple + " vs " + singleOnly);
    }

    @Test
    void texelsEqualTheReference() {
        double sunElevation = Math.toRadians(12);
        double sunAzimuth = 1.1;
        Vector3d sun = direction(sunAzimuth, sunElevation);
        for (AtmosphereTables t : new AtmosphereTables[] {multiple, single}) {
            SkyView view = SkyView.build(t, sunElevation, ALTITUDE);
            int[][] texels = {{0, 80}, {57, 100}, {191, 60}, {100, 20}, {10, 54}, {140, 107}};
            for (int[] xy : texels) {
                double[] d = SkyView.direction(xy[0] / (SkyView.WIDTH - 1.0), xy[1] / (SkyView.HEIGHT - 1.0));
                // Either side of the sun's plane sees the same sky.
                for (double side : new double[] {1, -1}) {
                    Vector3d expected = SkyReference.radiance(t,
                            direction(sunAzimuth + side * d[0], d[1]), sun, ALTITUDE);
                    for (int c = 0; c < 3; c++) {
                        double texel = view.texel(xy[0], xy[1], c);
                        assertEquals(expected.get(c), texel, 1e-5 * Math.abs(texel) + 1e-9,
                                "texel " + xy[0] + "," + xy[1] + " channel " + c);
                    }
                }
            }
        }
    }

    @Test
    void buildsAreDeterministic() {
        assertArrayEquals(SkyView.build(multiple, 0.3, ALTITUDE).rgb(), SkyView.build(multiple, 0.3, ALTITUDE).rgb());
    }

    @Test
    void uvAndDirectionRoundTrip() {
        for (double az = 0; az <= Math.PI; az += 0.1) {
            for (double el = -Math.PI / 2; el <= Math.PI / 2; el += 0.05) {
                double[] uv = SkyView.uv(az, el);
                double[] back = SkyView.direction(uv[0], uv[1]);
                // doubles: a map and its inverse agree to a few ε (2.2e-16) of angles ≤ 2π; 1e-12 and 1e-15 are round-
                // off bands
                assertEquals(az, back[0], 1e-12);
                assertEquals(el, back[1], 1e-12);
            }
        }
        // Azimuths fold into [0, pi]: the sky is symmetric about the sun's plane.
        assertArrayEquals(SkyView.uv(0.7, 0.2), SkyView.uv(-0.7, 0.2), 1e-15);
        assertArrayEquals(SkyView.uv(0.7, 0.2), SkyView.uv(2 * Math.PI - 0.7, 0.2), 1e-12);
    }

    @Test
    void uvFollowsTheDocumentedFormula() {
        for (double el : new double[] {-1.2, -0.3, -0.01, 0, 0.02, 0.4, 1.5}) {
            double v = 0.5 + 0.5 * Math.signum(el) * Math.sqrt(Math.abs(el) / (Math.PI / 2));
            assertEquals(v, SkyView.uv(0.4, el)[1], 1e-15);
            assertEquals(0.4 / Math.PI, SkyView.uv(0.4, el)[0], 1e-15);
        }
        // Texel (x, y) holds u = x/(W-1), v = y/(H-1): the shader's centre mapping 0.5/N + u(1 - 1/N) lands on it.
        for (int y : new int[] {0, 30, 53, 54, 107}) {
            double[] d = SkyView.direction(0, y / (SkyView.HEIGHT - 1.0));
            double v = SkyView.uv(d[0], d[1])[1];
            assertEquals((y + 0.5) / SkyView.HEIGHT, 0.5 / SkyView.HEIGHT + v * (1 - 1.0 / SkyView.HEIGHT), 1e-12);
        }
        assertEquals(Math.PI / 2, SkyView.direction(0, 1)[1], 1e-15);
        assertEquals(-Math.PI / 2, SkyView.direction(0, 0)[1], 1e-15);
    }

    /**
     * The shader reads the tables by the sizes Java builds them with: the sky system hands them to every program as
     * defines, and the include holds no size of its own but the one-texel stand-in's (no sky, no tables).
     */
    @Test
    void theShaderIncludeUsesTheJavaSizes() throws IOException {
        String glsl;
        try (InputStream in = SkyViewTest.class.getResourceAsStream("/shaders/sky/atmosphere.glsl")) {
            glsl = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        Map<String, Number> constants = new SkySystem().shaderConstants();
        assertEquals(Map.of("SKY_VIEW_WIDTH", SkyView.WIDTH, "SKY_VIEW_HEIGHT", SkyView.HEIGHT,
                "AERIAL_WIDTH", AerialPerspective.WIDTH, "AERIAL_HEIGHT", AerialPerspective.HEIGHT,
                "AERIAL_DEPTH", AerialPerspective.DEPTH, "AERIAL_MAX_DISTANCE", AerialPerspective.MAX_DISTANCE),
                constants);
        for (String name : constants.keySet()) {
            assertTrue(glsl.contains(name), name + " is read by the include");
        }
        assertTrue(glsl.contains("vec2(SKY_VIEW_WIDTH, SKY_VIEW_HEIGHT)"), "the sky view's size from the defines");
        assertFalse(glsl.contains("vec2(" + SkyView.WIDTH + ".0"), "no size of Java's written out in the include");
    }

    /** World direction at an azimuth (radians from +X toward +Z) and elevation. */
    static Vector3d direction(double azimuth, double elevation) {
        return new Vector3d(Math.cos(elevation) * Math.cos(azimuth), Math.sin(elevation),
                Math.cos(elevation) * Math.sin(azimuth));
    }
}

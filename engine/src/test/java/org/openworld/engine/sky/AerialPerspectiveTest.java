package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Vector3d;
import org.joml.Vector4d;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.openworld.engine.sky.AtmosphereSettings.Component;
import org.openworld.engine.sky.AtmosphereSettings.Scattering;

class AerialPerspectiveTest {
    // Tolerances here: the table's texels are floats (24-bit mantissa): 1e-6 on values up to 1, 1e-5 on products;
    // distances in double to 1e-9; 1e-3 where a short view's optical depth is near zero

    private static AtmosphereTables multiple;
    private static AtmosphereTables single;

    @BeforeAll
    static void build() {
        multiple = SkyColours.tables(Scattering.MULTIPLE, Component.BOTH);
        single = SkyColours.tables(Scattering.SINGLE, Component.BOTH);
    }

    @Test
    void inscatterGrowsAndTransmittanceFallsWithDistance() {
        for (AtmosphereTables t : new AtmosphereTables[] {multiple, single}) {
            AerialPerspective ap = AerialPerspective.scattered(t, Math.toRadians(35), 300);
            float[] rgba = ap.rgba();
            for (int y = 0; y < AerialPerspective.HEIGHT; y += 5) {
                for (int x = 0; x < AerialPerspective.WIDTH; x += 7) {
                    for (int z = 1; z < AerialPerspective.DEPTH; z++) {
                        int near = index(x, y, z - 1);
                        int far = index(x, y, z);
                        for (int c = 0; c < 3; c++) {
                            assertTrue(rgba[far + c] >= rgba[near + c], "inscatter at " + x + "," + y + "," + z);
                        }
                        assertTrue(rgba[far + 3] <= rgba[near + 3], "transmittance at " + x + "," + y + "," + z);
                    }
                }
            }
            // A level view 64 km through the lowest air: clearly hazy.
            Vector4d far = ap.sample(Math.PI / 2, 0.001, AerialPerspective.MAX_DISTANCE, new Vector4d());
            // 64 km of sea-level air: Rayleigh optical depth at 550 nm ≈ 0.1 per 8 km scale height × 8 ≈ 0.8, T ≈
            // e^-0.8 ≈ 0.45 before the haze, so T < 0.6; 0.05 catches a missing inscatter
            assertTrue(far.w < 0.6 && far.y > 0.05, t.settings().scattering() + ": " + far);
        }
    }

    @Test
    void nothingLiesBetweenTheEyeAndItself() {
        AerialPerspective ap = AerialPerspective.scattered(multiple, Math.toRadians(35), 300);
        Vector4d zero = ap.sample(1.0, 0.1, 0, new Vector4d());
        assertEquals(0, zero.x, 1e-12);
        assertEquals(1, zero.w, 1e-12);
        Vector4d close = ap.sample(1.0, 0.1, 1, new Vector4d());
        assertEquals(0, close.y, 1e-3);
        assertEquals(1, close.w, 1e-3);
    }

    @Test
    void slicesEndOnASquareLaw() {
        // doubles: 1e-9 m on distances of at most 64 km, far above rounding (ε 2.2e-16 × 6.4e4 ≈ 1e-11)
        assertEquals(AerialPerspective.MAX_DISTANCE, AerialPerspective.sliceEnd(AerialPerspective.DEPTH - 1), 1e-9);
        assertEquals(AerialPerspective.MAX_DISTANCE / 4, AerialPerspective.sliceEnd(AerialPerspective.DEPTH / 2 - 1),
                1e-9);
        assertEquals(AerialPerspective.MAX_DISTANCE / (32.0 * 32.0), AerialPerspective.sliceEnd(0), 1e-9);
    }

    @Test
    void theSimpleFogIsThePapersDistanceFogTowardsTheHorizon() {
        double fogDistance = 20_000;
        AtmosphereTables t = AtmosphereTables.build(AtmosphereSettings.DEFAULTS
                .withFog(AtmosphereSettings.Fog.SIMPLE, fogDistance));
        double sun = Math.toRadians(3);
        SkyView view = SkyView.build(t, sun, 300);
        float[] rgba = AerialPerspective.build(t, view, sun, 300).rgba();
        Vector3d horizon = new Vector3d();
        for (int x = 0; x < AerialPerspective.WIDTH; x += 5) {
            view.sample(Math.PI * x / (AerialPerspective.WIDTH - 1.0), 0, horizon);
            for (int z = 0; z < AerialPerspective.DEPTH; z += 3) {
                double transmittance = Math.exp(-AerialPerspective.sliceEnd(z) / fogDistance);
                for (int y = 0; y < AerialPerspective.HEIGHT; y += 7) {
                    int i = index(x, y, z);
                    // the texels are floats (24-bit mantissa): 1e-6 on values ≤ 1, 1e-5 on the inscatter's products
                    assertEquals(transmittance, rgba[i + 3], 1e-6, "e^(-d/D) at " + x + "," + y + "," + z);
                    assertEquals(horizon.x * (1 - transmittance), rgba[i], 1e-5, "red at " + x + "," + y + "," + z);
                    assertEquals(horizon.y * (1 - transmittance), rgba[i + 1], 1e-5);
                    assertEquals(horizon.z * (1 - transmittance), rgba[i + 2], 1e-5);
                }
            }
        }
        // Towards the low sun the fog takes the redder horizon there, not one colour all round.
        int toSun = index(0, 0, AerialPerspective.DEPTH - 1);
        int away = index(AerialPerspective.WIDTH - 1, 0, AerialPerspective.DEPTH - 1);
        // a low sun's horizon is orange towards it and blue-grey opposite: red/blue differs by far more than 1.5×
        assertTrue(rgba[toSun] / rgba[toSun + 2] > 1.5 * rgba[away] / rgba[away + 2], "fog redder towards the sun");
    }

    private static int index(int x, int y, int z) {
        return ((z * AerialPerspective.HEIGHT + y) * AerialPerspective.WIDTH + x) * 4;
    }
}

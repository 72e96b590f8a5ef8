package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Vector4d;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.openworld.engine.sky.AtmosphereSettings.Component;
import org.openworld.engine.sky.AtmosphereSettings.Scattering;

class AerialPerspectiveTest {

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
            AerialPerspective ap = AerialPerspective.build(t, Math.toRadians(35), 300);
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
            assertTrue(far.w < 0.6 && far.y > 0.05, t.settings().scattering() + ": " + far);
        }
    }

    @Test
    void nothingLiesBetweenTheEyeAndItself() {
        AerialPerspective ap = AerialPerspective.build(multiple, Math.toRadians(35), 300);
        Vector4d zero = ap.sample(1.0, 0.1, 0, new Vector4d());
        assertEquals(0, zero.x, 1e-12);
        assertEquals(1, zero.w, 1e-12);
        Vector4d close = ap.sample(1.0, 0.1, 1, new Vector4d());
        assertEquals(0, close.y, 1e-3);
        assertEquals(1, close.w, 1e-3);
    }

    @Test
    void slicesEndOnASquareLaw() {
        assertEquals(AerialPerspective.MAX_DISTANCE, AerialPerspective.sliceEnd(AerialPerspective.DEPTH - 1), 1e-9);
        assertEquals(AerialPerspective.MAX_DISTANCE / 4, AerialPerspective.sliceEnd(AerialPerspective.DEPTH / 2 - 1),
                1e-9);
        assertEquals(AerialPerspective.MAX_DISTANCE / (32.0 * 32.0), AerialPerspective.sliceEnd(0), 1e-9);
    }

    private static int index(int x, int y, int z) {
        return ((z * AerialPerspective.HEIGHT + y) * AerialPerspective.WIDTH + x) * 4;
    }
}

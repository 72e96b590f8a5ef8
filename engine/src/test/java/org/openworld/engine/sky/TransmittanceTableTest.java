package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

class TransmittanceTableTest {

    private static AtmosphereTables tables;

    @BeforeAll
    static void build() {
        tables = AtmosphereTables.build(AtmosphereSettings.DEFAULTS);
    }

    @Test
    void fallsTowardTheHorizon() {
        int n = tables.spectrum().count();
        double r = Atmosphere.BOTTOM_RADIUS + 500;
        double horizon = -Math.sqrt(1 - Math.pow(Atmosphere.BOTTOM_RADIUS / r, 2));
        double[] previous = tables.transmittance().transmittance(r, 1, new double[n]);
        for (int k = 1; k <= 100; k++) {
            double mu = 1 + (horizon + 1e-6 - 1) * k / 100.0;
            double[] t = tables.transmittance().transmittance(r, mu, new double[n]);
            for (int i = 0; i < n; i++) {
                assertTrue(t[i] <= previous[i] + 1e-12, "T must fall toward the horizon (mu " + mu + ")");
            }
            previous = t;
        }
        // a grazing path is ~40 air masses; the blue optical depth of one is ~0.3, so e^(-12) ≈ 6e-6: 1e-3 is far above
        // it
        assertTrue(previous[0] < 1e-3, "grazing blue light is almost all scattered away");
    }

    @Test
    void fallsWithDecreasingAltitude() {
        int n = tables.spectrum().count();
        double[] previous = tables.transmittance().transmittance(Atmosphere.TOP_RADIUS, 0.3, new double[n]);
        for (double altitude = 95_000; altitude >= 0; altitude -= 5_000) {
            double[] t = tables.transmittance().transmittance(Atmosphere.BOTTOM_RADIUS + altitude, 0.3,
                    new double[n]);
            for (int i = 0; i < n; i++) {
                assertTrue(t[i] <= previous[i] + 1e-12, "T must fall as the start goes down (" + altitude + " m)");
            }
            previous = t;
        }
        assertTrue(previous[0] < previous[n - 1], "blue is scattered more than red");
    }

    @Test
    void matchesAFineIntegral() {
        int n = tables.spectrum().count();
        double r = Atmosphere.BOTTOM_RADIUS + 2_000;
        double mu = 0.2;
        double length = Spheres.distanceToTop(r, mu);
        int steps = 20_000;
        double[] depth = new double[n];
        double[] extinction = new double[n];
        for (int s = 0; s < steps; s++) {
            double h = Spheres.radiusAt(r, mu, (s + 0.5) * length / steps) - Atmosphere.BOTTOM_RADIUS;
            tables.atmosphere().extinction(h, extinction);
            for (int i = 0; i < n; i++) {
                depth[i] += extinction[i] * length / steps;
            }
        }
        double[] table = tables.transmittance().transmittance(r, mu, new double[n]);
        for (int i = 0; i < n; i++) {
            assertEquals(Math.exp(-depth[i]), table[i], 5e-3 * Math.exp(-depth[i]), "wavelength " + i);
        }
    }

    @Test
    void isZeroBelowTheHorizon() {
        double[] t = tables.transmittance().transmittance(Atmosphere.BOTTOM_RADIUS + 100, -0.1,
                new double[tables.spectrum().count()]);
        for (double v : t) {
            assertEquals(0, v);
        }
    }
}

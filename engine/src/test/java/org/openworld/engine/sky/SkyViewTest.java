package org.openworld.engine.sky;

import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

class SkyViewTest {

    @Test
    void explore() {
        AtmosphereSettings d = AtmosphereSettings.DEFAULTS;
        AtmosphereSettings[] all = {d, d.withScattering(AtmosphereSettings.Scattering.SINGLE),
            new AtmosphereSettings(AtmosphereSettings.Scattering.SINGLE, d.component(), 8, 64, 64, 1, 1, 0.8, 0.3)};
        for (AtmosphereSettings s : all) {
            AtmosphereTables t = AtmosphereTables.build(s);
            System.out.println(s.scattering() + " " + s.outerSamples() + " tables " + t.buildMillis());
            for (double sunDeg : new double[] {60, 1, -4}) {
                double best = 1e9;
                SkyView v = null;
                for (int k = 0; k < 5; k++) {
                    v = SkyView.build(t, Math.toRadians(sunDeg), 100);
                    best = Math.min(best, v.buildMillis());
                }
                System.out.println(" sun " + sunDeg + " build " + best + " zenith "
                        + v.sample(0, Math.PI / 2, new Vector3d()));
            }
        }
    }
}

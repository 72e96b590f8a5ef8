package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Prints what the sky costs on this machine (build times for the report) and checks it stays interactive. */
class SkyTimingTest {

    @Test
    void buildTimes() {
        for (int wavelengths : new int[] {8, 15}) {
            AtmosphereSettings s = AtmosphereSettings.DEFAULTS.withWavelengths(wavelengths);
            double tables = Double.MAX_VALUE;
            double view = Double.MAX_VALUE;
            double aerial = Double.MAX_VALUE;
            // Best of three, after a first round that lets the JIT compile the loops.
            for (int round = 0; round < 4; round++) {
                AtmosphereTables t = AtmosphereTables.build(s);
                double v = SkyView.build(t, Math.toRadians(20), 100).buildMillis();
                double a = AerialPerspective.scattered(t, Math.toRadians(20), 100).buildMillis();
                if (round > 0) {
                    tables = Math.min(tables, t.buildMillis());
                    view = Math.min(view, v);
                    aerial = Math.min(aerial, a);
                }
            }
            System.out.printf("sky, %d wavelengths, %d cores: tables %.0f ms, sky view %.1f ms, aerial perspective"
                    + " %.1f ms%n", wavelengths, Runtime.getRuntime().availableProcessors(), tables, view, aerial);
            // loose ceilings (ms), two orders above the printed times: only a runaway fails, not a loaded machine
            assertTrue(view < 1000 && aerial < 1000 && tables < 10_000, "far too slow to follow the sun");
        }
    }
}

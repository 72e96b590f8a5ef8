package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.openworld.engine.sky.SkyColours.luminance;

import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.openworld.engine.sky.AtmosphereSettings.Component;
import org.openworld.engine.sky.AtmosphereSettings.Scattering;

/** The paper's figure 8: the sky lit by in-scattering from one kind of particle only. */
class ComponentTest {

    private static final double SUN = Math.toRadians(30);

    @Test
    void eachComponentGivesItsOwnSky() {
        float[] both = view(Component.BOTH).rgb();
        float[] rayleigh = view(Component.RAYLEIGH).rgb();
        float[] mie = view(Component.MIE).rgb();
        // 1e-2 of linear radiance: a thousand times the tables' float rounding, so equal skies cannot pass
        assertTrue(maxDifference(both, rayleigh) > 1e-2);
        assertTrue(maxDifference(both, mie) > 1e-2);
        assertTrue(maxDifference(rayleigh, mie) > 1e-2);
    }

    /**
     * Aerosols scatter mostly forward (g = 0.8), so the Mie-only sky peaks around the sun. The band within 10° of
     * the horizon is left out: there the long path through the haze layer glows toward the sun's azimuth too.
     */
    @Test
    void mieIsBrightestNearTheSun() {
        SkyView mie = view(Component.MIE);
        SkyView rayleigh = view(Component.RAYLEIGH);
        double bestLuminance = -1;
        double bestAngle = 0;
        Vector3d sun = SkyViewTest.direction(0, SUN);
        Vector3d rgb = new Vector3d();
        for (int y = SkyView.HEIGHT / 2; y < SkyView.HEIGHT; y++) {
            for (int x = 0; x < SkyView.WIDTH; x++) {
                double[] d = SkyView.direction(x / (SkyView.WIDTH - 1.0), y / (SkyView.HEIGHT - 1.0));
                if (d[1] < Math.toRadians(10)) {
                    continue;
                }
                rgb.set(mie.texel(x, y, 0), mie.texel(x, y, 1), mie.texel(x, y, 2));
                double l = luminance(rgb);
                if (l > bestLuminance) {
                    bestLuminance = l;
                    bestAngle = SkyViewTest.direction(d[0], d[1]).angle(sun);
                }
            }
        }
        assertTrue(bestAngle < Math.toRadians(5), "brightest Mie texel is " + Math.toDegrees(bestAngle)
                + " degrees from the sun");
        // Near the sun over opposite it: far larger for the aerosols than for the molecules.
        double mieContrast = luminance(mie.sample(0, SUN + Math.toRadians(3), new Vector3d()))
                / luminance(mie.sample(Math.PI, SUN, new Vector3d()));
        double rayleighContrast = luminance(rayleigh.sample(0, SUN + Math.toRadians(3), new Vector3d()))
                / luminance(rayleigh.sample(Math.PI, SUN, new Vector3d()));
        // Henyey–Greenstein with g = 0.8: (1 + g² + 2g)^1.5 / (1 + g² - 2g cos 3°)^1.5 ≈ 5.8 / 0.0087 ≈ 670× between 3°
        // and 180°; Rayleigh's (1 + cos²θ) gives about 1×: 10× leaves ample room for the different path lengths
        assertTrue(mieContrast > 10 * rayleighContrast, mieContrast + " vs " + rayleighContrast);
    }

    private static SkyView view(Component component) {
        return SkyView.build(SkyColours.tables(Scattering.MULTIPLE, component), SUN, 100);
    }

    private static double maxDifference(float[] a, float[] b) {
        double max = 0;
        for (int i = 0; i < a.length; i++) {
            max = Math.max(max, Math.abs(a[i] - b[i]));
        }
        return max;
    }
}

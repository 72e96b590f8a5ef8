package org.openworld.engine.environment;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.function.Function;
import org.joml.Vector3d;
import org.joml.Vector3f;
import org.joml.Vector3fc;
import org.junit.jupiter.api.Test;

class SkyIrradianceTest {
    // Tolerances here: 1e-3 where the sky is integrated over its view's finite texels (a quadrature); 1e-5 to 1e-6
    // where float rounding is all that is left; 1e-9 for doubles

    /** Midpoint-rule steps over θ (0..π) for projecting a function of direction. */
    private static final int STEPS = 180;

    /** Projects the grey radiance f(direction) by quadrature over the whole sphere. */
    static SkyIrradiance project(Function<Vector3d, Double> f) {
        SkyIrradiance sh = new SkyIrradiance();
        double dTheta = Math.PI / STEPS;
        double dPhi = 2 * Math.PI / (2 * STEPS);
        for (int j = 0; j < STEPS; j++) {
            double theta = (j + 0.5) * dTheta;
            for (int i = 0; i < 2 * STEPS; i++) {
                double phi = (i + 0.5) * dPhi;
                Vector3d d = new Vector3d(Math.sin(theta) * Math.cos(phi), Math.cos(theta),
                        Math.sin(theta) * Math.sin(phi));
                double l = f.apply(d);
                sh.add(d, new Vector3d(l), Math.sin(theta) * dTheta * dPhi);
            }
        }
        return sh;
    }

    static double grey(SkyIrradiance sh, Vector3d n) {
        Vector3d e = sh.irradiance(new Vector3d(n).normalize(), new Vector3d());
        // doubles: equal inputs in every channel give equal sums, to round-off
        assertEquals(e.x, e.z, 1e-9, "a grey sky gives grey light");
        return e.y;
    }

    @Test
    void projectingASumOfHarmonicsGivesBackItsWeights() {
        double[] weights = {1.5, -0.4, 0.7, 0.2, -0.3, 0.25, 0.6, -0.15, 0.35};
        SkyIrradiance sh = project(d -> {
            double[] y = SkyIrradiance.harmonics(d);
            double sum = 0;
            for (int i = 0; i < y.length; i++) {
                sum += weights[i] * y[i];
            }
            return sum;
        });
        for (int i = 0; i < SkyIrradiance.COUNT; i++) {
            // 1e-3: the coefficients are integrated over the sky view's finite texels (a quadrature), not in closed
            // form; 1e-5 to 1e-6 where only float rounding is left
            assertEquals(weights[i], sh.coefficient(i, new Vector3d()).y, 1e-3, "coefficient " + i);
        }
    }

    @Test
    void aUniformSkyGivesPiTimesItsRadianceOnEveryNormal() {
        SkyIrradiance sh = project(d -> 2.0);
        for (Vector3d n : new Vector3d[] {new Vector3d(0, 1, 0), new Vector3d(0, -1, 0), new Vector3d(1, 2, -3)}) {
            assertEquals(2 * Math.PI, grey(sh, n), 1e-3, "normal " + n);
        }
    }

    /**
     * A clamped-cosine lobe L = max(a·ω, 0): irradiance 2π/3 facing the lobe (∫ cos² over a hemisphere), 2/3 across
     * it (∫ x·z over a quarter sphere) and 0 facing away; order 2 is within 1 % of the largest.
     */
    @Test
    void aCosineLobeMatchesTheClosedFormWithinOnePerCent() {
        Vector3d a = new Vector3d(0.3, 0.8, -0.5).normalize();
        SkyIrradiance sh = project(d -> Math.max(d.dot(a), 0));
        Vector3d across = new Vector3d(a).cross(0, 0, 1).normalize();
        double peak = 2 * Math.PI / 3;
        // 1 % of the peak: the cosine kernel leaves little beyond order 2 (its coefficients fall as 1/l², Ramamoorthi
        // and Hanrahan), the bound the Javadoc states
        assertEquals(peak, grey(sh, a), 0.01 * peak, "facing the lobe");
        assertEquals(2.0 / 3, grey(sh, across), 0.01 * peak, "across it");
        assertEquals(0, grey(sh, new Vector3d(a).negate()), 0.01 * peak, "facing away");
    }

    @Test
    void theGroundsHemisphereInClosedFormIsItsProjectionAndGivesPiLTimesOneMinusNyOverTwo() {
        SkyIrradiance closed = new SkyIrradiance().addLowerHemisphere(new Vector3d(0.5));
        SkyIrradiance projected = project(d -> d.y < 0 ? 0.5 : 0.0);
        for (int i = 0; i < SkyIrradiance.COUNT; i++) {
            assertEquals(projected.coefficient(i, new Vector3d()).y, closed.coefficient(i, new Vector3d()).y, 2e-3,
                    "coefficient " + i);
        }
        for (double ny : new double[] {1, 0.5, 0, -0.7, -1}) {
            Vector3d n = new Vector3d(Math.sqrt(1 - ny * ny), ny, 0);
            assertEquals(Math.PI * 0.5 * (1 - ny) / 2, grey(closed, n), 1e-5, "n.y " + ny);
        }
    }

    @Test
    void theShaderFactorsGiveTheSameIrradianceAsTheHarmonics() {
        SkyIrradiance sh = project(d -> 1 + d.x - 0.5 * d.y * d.z + Math.max(d.y, 0));
        Vector3fc[] c = sh.shaderFactors();
        Vector3d n = new Vector3d(0.4, -0.5, 0.77).normalize();
        double x = n.x;
        double y = n.y;
        double z = n.z;
        double[] poly = {1, y, z, x, x * y, y * z, 3 * y * y - 1, x * z, x * x - z * z};
        double shader = 0;
        for (int i = 0; i < poly.length; i++) {
            shader += c[i].y() * poly[i];
        }
        assertEquals(grey(sh, n), shader, 1e-5);
    }

    @Test
    void aSunWithoutASkySystemHasAUniformSkyAsBrightAsItsAmbientOverABlackGround() {
        Sun sun = new Sun(new Vector3f(0, 1, 0), new Vector3f(1), new Vector3f(0.2f, 0.3f, 0.4f));
        Vector3d up = sun.sky().irradiance(new Vector3d(0, 1, 0), new Vector3d());
        assertEquals(0.3, up.y, 1e-6);
        assertEquals(0.4, up.z, 1e-6);
        assertEquals(0.15, sun.sky().irradiance(new Vector3d(1, 0, 0), new Vector3d()).y, 1e-6, "half on a wall");
        assertEquals(0, sun.sky().irradiance(new Vector3d(0, -1, 0), new Vector3d()).y, 1e-6, "none from below");
    }
}

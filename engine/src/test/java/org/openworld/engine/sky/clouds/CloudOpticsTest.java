package org.openworld.engine.sky.clouds;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.function.DoubleUnaryOperator;
import org.junit.jupiter.api.Test;

/** The clouds' height profile and phase function against their formulas and the properties they must have. */
class CloudOpticsTest {

    /** Midpoint sums over μ in −1..1: with this many the sum of a smooth phase is exact to about 1e-6. */
    private static final int STEPS = 200_000;

    /** ∫ f(μ) dΩ over the sphere for a function of μ alone: 2π ∫ f dμ. */
    private static double overSphere(DoubleUnaryOperator f) {
        double sum = 0;
        double dmu = 2.0 / STEPS;
        for (int i = 0; i < STEPS; i++) {
            sum += f.applyAsDouble(-1 + (i + 0.5) * dmu) * dmu;
        }
        return 2 * Math.PI * sum;
    }

    @Test
    void henyeyGreensteinIsNormalisedWithMeanCosineG() {
        for (double g : new double[] {-0.3, 0, 0.4, 0.8}) {
            // a phase function integrates to 1 over the sphere, and HG's mean cosine is its g (its definition)
            assertEquals(1, overSphere(mu -> CloudOptics.henyeyGreenstein(mu, g)), 1e-5, "g " + g);
            assertEquals(g, overSphere(mu -> mu * CloudOptics.henyeyGreenstein(mu, g)), 1e-5, "g " + g);
        }
        assertEquals(1 / (4 * Math.PI), CloudOptics.henyeyGreenstein(0.3, 0), 1e-15, "g 0 is isotropic");
        // the formula at a point, written out: (1 - g^2) / (4 pi (1 + g^2 - 2 g mu)^1.5)
        assertEquals((1 - 0.64) / (4 * Math.PI * Math.pow(1 + 0.64 - 1.6 * 0.5, 1.5)),
                CloudOptics.henyeyGreenstein(0.5, 0.8), 1e-12);
    }

    @Test
    void dualLobeIsNormalisedWithTheWeightedMeanCosine() {
        for (double scale : new double[] {1, CloudOptics.OCTAVE_C, CloudOptics.OCTAVE_C * CloudOptics.OCTAVE_C}) {
            double expected = scale * (CloudOptics.FORWARD_SHARE * CloudOptics.FORWARD
                    + (1 - CloudOptics.FORWARD_SHARE) * CloudOptics.BACKWARD);
            assertEquals(1, overSphere(mu -> CloudOptics.phase(mu, scale)), 1e-5);
            assertEquals(expected, overSphere(mu -> mu * CloudOptics.phase(mu, scale)), 1e-5);
        }
        // the silver lining: towards the sun the phase is many times the isotropic 1/4pi, and the back lobe lifts the
        // side away from the sun above the forward lobe alone
        assertTrue(CloudOptics.phase(1, 1) > 20 / (4 * Math.PI));
        assertTrue(CloudOptics.phase(-1, 1)
                > CloudOptics.FORWARD_SHARE * CloudOptics.henyeyGreenstein(-1, CloudOptics.FORWARD));
        // each octave is less peaked than the one before
        assertTrue(CloudOptics.phase(1, 1) > CloudOptics.phase(1, CloudOptics.OCTAVE_C));
    }

    @Test
    void theTableAsTheShaderReadsItKeepsThePhaseNormalised() {
        float[] table = CloudOptics.table(1);
        for (int channel = 1; channel <= 3; channel++) {
            double sum = 0;
            for (int i = 0; i < CloudOptics.SIZE; i++) {
                sum += table[4 * i + channel] * (2.0 / CloudOptics.SIZE);
            }
            // midpoint sum over 256 texels of the forward lobe's peak (g = 0.8: half its height within 0.03 of mu =
            // 1, four texels) and float rounding: 1 % is the error of such a sum there
            assertEquals(1, 2 * Math.PI * sum, 0.01, "octave " + (channel - 1));
        }
    }

    @Test
    void stratusIsALowSheetAndCumulusRisesAsHighAsItsCover() {
        for (double h : new double[] {0, 1}) {
            assertEquals(0, CloudOptics.heightProfile(h, 0), 1e-12, "stratus at " + h);
            assertEquals(0, CloudOptics.heightProfile(h, 1), 1e-12, "cumulus at " + h);
        }
        // stratus: full between 5 and 10 % of the layer, nothing above a quarter
        assertEquals(1, CloudOptics.heightProfile(0.07, 0), 1e-12);
        assertEquals(0, CloudOptics.heightProfile(0.3, 0), 1e-12);
        // cumulus: 1 - h above the base's ramp, so a cover of c reaches h = c (cover + profile - 1 > 0)
        for (double h = 0.1; h < 1; h += 0.1) {
            assertEquals(1 - h, CloudOptics.heightProfile(h, 1), 1e-12, "cumulus at " + h);
        }
        // types between blend linearly
        assertEquals(0.5 * CloudOptics.heightProfile(0.5, 0) + 0.5 * CloudOptics.heightProfile(0.5, 1),
                CloudOptics.heightProfile(0.5, 0.5), 1e-12);
    }
}

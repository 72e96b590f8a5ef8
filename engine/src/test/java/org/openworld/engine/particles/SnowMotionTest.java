package org.openworld.engine.particles;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.openworld.engine.core.HeightField;

/** The update rule against its analysis: terminal velocity, the wind, the Brownian spread, the cube and the ground. */
class SnowMotionTest {
    // Tolerances here: float state (24-bit mantissa, ~6e-8 relative) on positions of tens of metres rounds at ~4e-6 m a
    // step, so 1e-4 to 1e-3 m; velocities of a few m/s to 1e-6; the cube's half-side (20 m) bounds a flake exactly

    static final float DT = 1f / 60;
    /** Ground far below the cube, so nothing lands. */
    static final GroundPatch DEEP = GroundPatch.sample((x, z) -> -1e4, 0, 0, 100, 8);
    static final SnowMotion.Volume CUBE = new SnowMotion.Volume(new Vector3f(0, 50, 0), 40);

    static float[] atRest(int count) {
        float[] state = new float[count * SnowMotion.FLOATS];
        for (int i = 0; i < count; i++) {
            state[i * SnowMotion.FLOATS + 1] = 50; // at the cube's centre, still
        }
        return state;
    }

    @ParameterizedTest
    @CsvSource({"9.81, 9.81", "2, 2", "20, 20", "1, 0.5", "3, 10"})
    void inStillAirTheFallSettlesAtGravityOverDragAlongTheExponential(float gravity, float drag) {
        SnowMotion.Forces forces = new SnowMotion.Forces(gravity, drag, 0, new Vector3f(), DT);
        float[] state = atRest(1);
        double terminal = SnowMotion.terminalVelocity(gravity, drag);
        int oneTimeConstant = Math.round(1 / (drag * DT));
        for (int n = 1; n <= 40 * oneTimeConstant; n++) {
            SnowMotion.step(state, forces, CUBE, DEEP, n);
            if (n == oneTimeConstant) {
                // v(t) = -(g/k)(1 - e^(-kt)) at t = 1/k, within the Euler step's error, of order k dt
                double expected = -terminal * (1 - Math.exp(-n * DT * drag));
                assertEquals(expected, state[4], terminal * (drag * DT + 1e-3), "after one time constant");
            }
        }
        assertEquals(-gravity / drag, state[4], 1e-5 * terminal, "terminal velocity g / k");
        assertEquals(0, state[3], 0);
        assertEquals(0, state[5], 0);
    }

    @Test
    void theFlakesTakeOnTheWindsVelocity() {
        Vector3f wind = new Vector3f(3, 0, -2);
        float[] state = atRest(1);
        for (int n = 0; n < 2000; n++) {
            SnowMotion.step(state, new SnowMotion.Forces(1, 2, 0, wind, DT), CUBE, DEEP, n);
        }
        assertEquals(3, state[3], 1e-4);
        assertEquals(-0.5, state[4], 1e-4);
        assertEquals(-2, state[5], 1e-4);
    }

    @Test
    void theBrownianTermSpreadsTheVelocityToItsSettledVariance() {
        float drag = 2;
        ParticleSettings s = new ParticleSettings(20_000, 1, drag, 0.3, 0.02, 40, 0.3);
        float kick = (float) (s.brownian() * Math.sqrt(DT));
        float[] state = atRest(s.count());
        for (int n = 0; n < 600; n++) { // ten time constants: the spread is within e^-20 of settled
            SnowMotion.step(state, new SnowMotion.Forces((float) s.gravity(), drag, kick, new Vector3f(), DT), CUBE,
                    DEEP, SnowMotion.stepKey(7, n));
        }
        double settled = SnowMotion.settledVariance(s.brownian(), drag, DT);
        for (int axis = 0; axis < 3; axis++) {
            double mean = axis == 1 ? -s.fallSpeed() : 0;
            double sum = 0;
            for (int i = 0; i < s.count(); i++) {
                double d = state[i * SnowMotion.FLOATS + 3 + axis] - mean;
                sum += d * d;
            }
            double variance = sum / s.count();
            // 20 000 samples: the variance's own relative spread is sqrt(2 / N) = 1 %
            assertEquals(settled, variance, 0.05 * settled, "axis " + axis);
        }
        // and the setting's meaning: the RMS random speed is turbulence, up to the step's O(k dt)
        assertEquals(s.turbulence(), Math.sqrt(settled), 0.01 * s.turbulence());
    }

    @Test
    void theRandomNumbersAreStandardNormalAndNewEachStep() {
        float[] xi = new float[3];
        double sum = 0;
        double squares = 0;
        int n = 30_000;
        for (int i = 0; i < n; i++) {
            SnowMotion.gaussians(i ^ SnowMotion.stepKey(1, 0), xi);
            for (float x : xi) {
                sum += x;
                squares += x * x;
            }
        }
        // 3n = 90 000 standard normal samples: the mean's standard error is 1 / √90 000 = 0.0033 and that of the
        // mean square (variance 2 per sample) √(2 / 90 000) = 0.0047, so both bands are six standard errors wide
        assertEquals(0, sum / (3 * n), 0.02);
        assertEquals(1, squares / (3 * n), 0.03);
        float[] again = new float[3];
        SnowMotion.gaussians(5 ^ SnowMotion.stepKey(1, 0), xi);
        SnowMotion.gaussians(5 ^ SnowMotion.stepKey(1, 0), again);
        assertEquals(xi[0], again[0], 0, "seeded: the same numbers again");
        SnowMotion.gaussians(5 ^ SnowMotion.stepKey(1, 1), again);
        assertNotEquals(xi[0], again[0], "the next step draws anew");
        assertNotEquals(SnowMotion.stepKey(1, 0), SnowMotion.stepKey(2, 0), "another seed, another run");
    }

    @Test
    void aFlakeLeavingTheCubeComesBackInOnTheOtherSide() {
        float[] state = {19.9f, 50, -19.9f, 12, 0, -12}; // near the east and north faces, moving out of both
        SnowMotion.step(state, new SnowMotion.Forces(0, 1e-6f, 0, new Vector3f(), 0.1f), CUBE, DEEP, 0);
        assertEquals(-20 + 1.1f, state[0], 1e-3);
        assertEquals(20 - 1.1f, state[2], 1e-3);
        assertEquals(50, state[1], 1e-3);
    }

    @Test
    void aFlakeComingBackThroughASideFaceKeepsItsHeightAboveTheGround() {
        GroundPatch slope = GroundPatch.sample((x, z) -> 40 + 0.25 * x, 0, 0, 100, 64);
        float[] state = {-19.9f, 45, 0, -2, 0, 0}; // by the west face, leaving through it to x = -20.1
        double heightWhereItLeft = 45 - (40 + 0.25 * -20.1);
        SnowMotion.step(state, new SnowMotion.Forces(0, 1e-6f, 0, new Vector3f(), 0.1f), CUBE, slope, 0);
        assertEquals(20 - 0.1f, state[0], 1e-3, "in again by the east face");
        assertEquals(heightWhereItLeft, state[1] - (40 + 0.25f * state[0]), 1e-3, "as high above the ground");
        assertTrue(state[1] > 45 + 9.9, "so 10 m higher up, where the ground is 10 m higher");
    }

    @Test
    void aFlakeThatReachesTheGroundStartsAgainAtTheTopOfTheCube() {
        GroundPatch slope = GroundPatch.sample((x, z) -> 30 + 0.1 * x, 0, 0, 100, 32);
        float[] state = {0, 30.05f, 0, 0, -1, 0}; // 5 cm above the ground, falling 1 m/s
        SnowMotion.step(state, new SnowMotion.Forces(1, 1, 0, new Vector3f(), 0.1f), CUBE, slope, 0);
        float below = 30 - (30.05f - 0.1f); // 5 cm below the ground after the step
        assertEquals(70 - below, state[1], 1e-4, "as far under the top as it went under the ground");
        assertEquals(-1, state[4], 1e-6, "it keeps its velocity");
    }

    @Test
    void aFreshFallFillsTheAirOfTheCubeEvenlyAndNothingUnderground() {
        HeightField hill = (x, z) -> 50 + 0.5 * x; // the ground cuts the cube diagonally
        GroundPatch ground = GroundPatch.sample(hill, 0, 0, 80, 64);
        Vector3f steady = new Vector3f(1, -1, 0);
        float[] state = SnowMotion.seed(40_000, CUBE, ground, steady, 3);
        int[] perHalf = new int[2];
        for (int i = 0; i < 40_000; i++) {
            int o = i * SnowMotion.FLOATS;
            assertTrue(Math.abs(state[o]) <= 20 && Math.abs(state[o + 1] - 50) <= 20 && Math.abs(state[o + 2]) <= 20);
            assertTrue(state[o + 1] >= ground.heightAt(state[o], state[o + 2]), "flake " + i + " underground");
            assertEquals(-1, state[o + 4], 0);
            perHalf[state[o] < 0 ? 0 : 1]++;
        }
        // the air above 50 + x/2 in the cube x, z in [-20, 20], y in [30, 70] is on average 25 m deep in the west
        // half and 15 m in the east half: 25/40 of the flakes belong in the west
        assertEquals(25.0 / 40, perHalf[0] / 40_000.0, 0.01, "evenly through the air, more where there is more");
    }
}

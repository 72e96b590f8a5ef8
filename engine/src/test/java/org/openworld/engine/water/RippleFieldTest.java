package org.openworld.engine.water;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The ripple tile: the loop, the amplitude, the wind's direction in shape and motion, the seed, the packing. */
class RippleFieldTest {

    private static final double TILE = 8; // metres
    private static final double PERIOD = 20; // seconds
    private static final double WIND = 6; // m/s
    private static final double RMS = 0.12; // about Cox and Munk's √(0.003 + 0.00512 · 6) = 0.18, scaled down

    private static RippleField field(int size, int frames, double windDegrees, long seed) {
        return RippleField.synthesize(size, frames, TILE, PERIOD, WIND, windDegrees, RMS, seed);
    }

    /** The largest difference between two fields' slopes. */
    private static double maxSlopeDifference(RippleField.Frame a, RippleField.Frame b) {
        double max = 0;
        for (int i = 0; i < a.slopes().length; i++) {
            max = Math.max(max, Math.abs(a.slopes()[i] - b.slopes()[i]));
        }
        return max;
    }

    @Test
    void fieldRepeatsAfterOnePeriodAndMovesWithinIt() {
        RippleField f = field(32, 8, 30, 1);
        double tolerance = 1e-5 * RMS;
        assertTrue(maxSlopeDifference(f.frame(0), f.fieldAt(PERIOD)) <= tolerance, "t = period is frame 0");
        assertTrue(maxSlopeDifference(f.fieldAt(0.37 * PERIOD), f.fieldAt(1.37 * PERIOD)) <= tolerance,
                "t and t + period");
        assertTrue(maxSlopeDifference(f.fieldAt(0.37 * PERIOD), f.fieldAt(-0.63 * PERIOD)) <= tolerance,
                "t and t − period");
        for (int k = 0; k < 8; k++) {
            assertTrue(maxSlopeDifference(f.frame(k), f.fieldAt(k * PERIOD / 8)) <= tolerance,
                    "frame " + k + " is the field at " + k + "/8 of the period");
        }
        // and it is not trivially periodic: half a period later the slopes are others
        RippleField.Frame half = f.fieldAt(PERIOD / 2);
        double sum = 0;
        for (int i = 0; i < half.slopes().length; i++) {
            double d = half.slopes()[i] - f.frame(0).slopes()[i];
            sum += d * d;
        }
        // two independent fields of RMS σ differ by √2 σ: half of σ is far below it, a frozen field gives 0
        assertTrue(Math.sqrt(sum / (32 * 32)) > 0.5 * RMS, "the field moves within the period");
    }

    @Test
    void framesOfAFourFrameLoopAreEveryOtherFrameOfAnEightFrameLoop() {
        RippleField four = field(32, 4, 120, 2);
        RippleField eight = field(32, 8, 120, 2);
        // Each synthesis normalises over its own frames, so the two may differ by one constant factor, close to 1.
        double num = 0;
        double den = 0;
        for (int k = 0; k < 4; k++) {
            float[] a = four.frame(k).slopes();
            float[] b = eight.frame(2 * k).slopes();
            for (int i = 0; i < a.length; i++) {
                num += (double) a[i] * b[i];
                den += (double) b[i] * b[i];
            }
        }
        double factor = num / den;
        // each synthesis normalises over its own frames (4 or 8 samples of the variance): 5 % covers that sampling
        // difference
        assertEquals(1, factor, 0.05, "amplitude factor between the two loops");
        for (int k = 0; k < 4; k++) {
            float[] a = four.frame(k).slopes();
            float[] b = eight.frame(2 * k).slopes();
            for (int i = 0; i < a.length; i++) {
                assertEquals(a[i], factor * b[i], 1e-5 * RMS, "frame " + k + " of 4 vs frame " + 2 * k + " of 8");
            }
        }
    }

    @ParameterizedTest
    @ValueSource(ints = {1, 3, 8})
    void rmsSlopeIsTheRequestedOneAndTheMeanSlopeZero(int frames) {
        int size = 64;
        double target = 0.137;
        RippleField f = RippleField.synthesize(size, frames, TILE, PERIOD, WIND, 75, target, 3);
        double sumX = 0;
        double sumZ = 0;
        double sum2 = 0;
        for (int frame = 0; frame < frames; frame++) {
            for (int z = 0; z < size; z++) {
                for (int x = 0; x < size; x++) {
                    double sx = f.slopeX(frame, x, z);
                    double sz = f.slopeZ(frame, x, z);
                    sumX += sx;
                    sumZ += sz;
                    sum2 += sx * sx + sz * sz;
                }
            }
        }
        double n = (double) frames * size * size;
        assertEquals(target, Math.sqrt(sum2 / n), 1e-3 * target, "RMS slope over texels and frames");
        assertEquals(target, f.rmsSlope(), 1e-3 * target, "rmsSlope()");
        assertEquals(0, sumX / n, 1e-4 * target, "mean ∂h/∂x");
        assertEquals(0, sumZ / n, 1e-4 * target, "mean ∂h/∂z");
    }

    /**
     * Slope variance along and across the wind direction: the wind must pick the axis, with x east, z south. Phillips'
     * spreading gives 3× along the wind on average; one 8 m tile holds few long waves, so a single draw ranges from
     * about 2× to 6×, and the variances are pooled over four seeds.
     */
    @ParameterizedTest
    @ValueSource(doubles = {0, 90, 225, 300})
    void slopesVaryMoreAlongTheWindThanAcrossIt(double windDegrees) {
        int size = 64;
        int frames = 4;
        double windX = Math.sin(Math.toRadians(windDegrees));
        double windZ = -Math.cos(Math.toRadians(windDegrees));
        double along = 0;
        double across = 0;
        double varX = 0;
        double varZ = 0;
        for (long seed = 4; seed < 8; seed++) {
            RippleField f = field(size, frames, windDegrees, seed);
            for (int frame = 0; frame < frames; frame++) {
                for (int z = 0; z < size; z++) {
                    for (int x = 0; x < size; x++) {
                        double sx = f.slopeX(frame, x, z);
                        double sz = f.slopeZ(frame, x, z);
                        along += Math.pow(sx * windX + sz * windZ, 2);
                        across += Math.pow(-sx * windZ + sz * windX, 2);
                        varX += sx * sx;
                        varZ += sz * sz;
                    }
                }
            }
        }
        // the directional factor |k̂·ŵ|² of the spectrum weights slope variance along : across as ⟨cos⁴⟩ : ⟨cos² sin²⟩
        // = 3 : 1; 2 is under that
        assertTrue(along > 2 * across, "along " + along + " vs across " + across);
        if (windDegrees == 0) {
            assertTrue(varZ > 2 * varX, "wind towards north: var(sz) " + varZ + " vs var(sx) " + varX);
        } else if (windDegrees == 90) {
            assertTrue(varX > 2 * varZ, "wind towards east: var(sx) " + varX + " vs var(sz) " + varZ);
        }
    }

    /**
     * The slope pattern a moment later is the earlier one shifted downwind: the peak of their cross-correlation
     * lies along +ŵ. Fails when the waves run upwind (e^{+iωt} on h0(k)) or when x and z are swapped.
     */
    @ParameterizedTest
    @ValueSource(doubles = {90, 200, 315})
    void wavesTravelDownwind(double windDegrees) {
        int size = 64;
        RippleField f = field(size, 1, windDegrees, 5);
        RippleField.Frame before = f.fieldAt(0);
        RippleField.Frame after = f.fieldAt(0.25); // s
        int reach = 8; // texels, 1 m: more than the fastest wave here (3.5 m/s) covers in 0.25 s
        double best = Double.NEGATIVE_INFINITY;
        int bestX = 0;
        int bestZ = 0;
        for (int dz = -reach; dz <= reach; dz++) {
            for (int dx = -reach; dx <= reach; dx++) {
                double c = 0;
                for (int z = 0; z < size; z++) {
                    for (int x = 0; x < size; x++) {
                        int x1 = Math.floorMod(x + dx, size);
                        int z1 = Math.floorMod(z + dz, size);
                        c += before.slopeX(x, z) * after.slopeX(x1, z1) + before.slopeZ(x, z) * after.slopeZ(x1, z1);
                    }
                }
                if (c > best) {
                    best = c;
                    bestX = dx;
                    bestZ = dz;
                }
            }
        }
        double windX = Math.sin(Math.toRadians(windDegrees));
        double windZ = -Math.cos(Math.toRadians(windDegrees));
        double along = bestX * windX + bestZ * windZ;
        double across = Math.abs(-bestX * windZ + bestZ * windX);
        String shift = "pattern shifted by (" + bestX + ", " + bestZ + ") texels";
        assertTrue(along >= 1, shift + ": at least one texel downwind");
        // within tan⁻¹ 0.6 ≈ 31° of the wind
        assertTrue(across <= 0.6 * along, shift + ": mostly along the wind");
    }

    @Test
    void sameSeedSameFieldOtherSeedOtherField() {
        RippleField a = field(32, 2, 45, 11);
        RippleField b = field(32, 2, 45, 11);
        RippleField c = field(32, 2, 45, 12);
        for (int frame = 0; frame < 2; frame++) {
            assertArrayEquals(a.frame(frame).slopes(), b.frame(frame).slopes(), "same seed, frame " + frame);
            assertArrayEquals(a.frame(frame).heights(), b.frame(frame).heights(), "same seed, frame " + frame);
            assertTrue(maxSlopeDifference(a.frame(frame), c.frame(frame)) > RMS, "another seed, frame " + frame);
        }
    }

    /**
     * The slopes are the x and z derivatives of the heights, checked with a plain DFT written here: it fixes the
     * spectral derivative's sign, the axes (rows are z) and the units (rad/m from the tile size).
     */
    @Test
    void slopesAreTheDerivativesOfTheHeights() {
        int n = 16;
        RippleField f = field(n, 1, 160, 6);
        RippleField.Frame frame = f.frame(0);
        // forward DFT of the heights: H(m, q) = Σ h(x, z) e^{−2πi (m x + q z) / n} / n²
        double[] re = new double[n * n];
        double[] im = new double[n * n];
        for (int q = 0; q < n; q++) {
            for (int m = 0; m < n; m++) {
                for (int z = 0; z < n; z++) {
                    for (int x = 0; x < n; x++) {
                        double angle = -2 * Math.PI * (m * x + q * z) / n;
                        re[q * n + m] += frame.height(x, z) * Math.cos(angle) / (n * n);
                        im[q * n + m] += frame.height(x, z) * Math.sin(angle) / (n * n);
                    }
                }
            }
        }
        double dk = 2 * Math.PI / TILE;
        for (int z = 0; z < n; z++) {
            for (int x = 0; x < n; x++) {
                double sx = 0;
                double sz = 0;
                for (int q = 0; q < n; q++) {
                    for (int m = 0; m < n; m++) {
                        int fm = m < n / 2 ? m : m - n;
                        int fq = q < n / 2 ? q : q - n;
                        double angle = 2 * Math.PI * (m * x + q * z) / n;
                        // Re(i k H e^{iθ}) = −k (H_re sin θ + H_im cos θ)
                        double d = -(re[q * n + m] * Math.sin(angle) + im[q * n + m] * Math.cos(angle));
                        sx += dk * fm * d;
                        sz += dk * fq * d;
                    }
                }
                assertEquals(sx, frame.slopeX(x, z), 1e-4 * RMS, "∂h/∂x at (" + x + ", " + z + ")");
                assertEquals(sz, frame.slopeZ(x, z), 1e-4 * RMS, "∂h/∂z at (" + x + ", " + z + ")");
            }
        }
    }

    /** Each layer holds its own frame's slopes in RG and the next frame's in BA, the last frame's next the first. */
    @Test
    void texelsDecodeToThisFrameAndTheNext() {
        int size = 32;
        int frames = 3;
        RippleField f = field(size, frames, 10, 7);
        float slopeScale = (float) (1.5 * RMS); // small enough that some texels clamp
        List<byte[]> texels = f.texels(slopeScale);
        assertEquals(frames, texels.size());
        double slopeStep = 0.5 / 127 * slopeScale * (1 + 1e-6);
        int clamped = 0;
        for (int frame = 0; frame < frames; frame++) {
            byte[] rgba = texels.get(frame);
            int next = (frame + 1) % frames;
            assertEquals(4 * size * size, rgba.length);
            for (int z = 0; z < size; z++) {
                for (int x = 0; x < size; x++) {
                    int i = 4 * (z * size + x);
                    double sx = f.slopeX(frame, x, z);
                    double sz = f.slopeZ(frame, x, z);
                    String at = " at (" + x + ", " + z + ") of frame " + frame;
                    assertEquals(clamp(sx, slopeScale), decode(rgba[i], slopeScale), slopeStep, "R" + at);
                    assertEquals(clamp(sz, slopeScale), decode(rgba[i + 1], slopeScale), slopeStep, "G" + at);
                    assertEquals(clamp(f.slopeX(next, x, z), slopeScale), decode(rgba[i + 2], slopeScale), slopeStep,
                            "B" + at);
                    assertEquals(clamp(f.slopeZ(next, x, z), slopeScale), decode(rgba[i + 3], slopeScale), slopeStep,
                            "A" + at);
                    clamped += Math.abs(sx) > slopeScale || Math.abs(sz) > slopeScale ? 1 : 0;
                }
            }
        }
        assertTrue(clamped > 0, "the test covers clamped texels too");
    }

    private static double decode(byte b, float slopeScale) {
        return ((b & 0xFF) - 128) / 127.0 * slopeScale;
    }

    private static double clamp(double v, double limit) {
        return Math.max(-limit, Math.min(limit, v));
    }

    @Test
    void argumentErrorsNameTheArgument() {
        assertNamed("size", () -> RippleField.synthesize(48, 4, TILE, PERIOD, WIND, 0, RMS, 1));
        assertNamed("size", () -> RippleField.synthesize(4, 4, TILE, PERIOD, WIND, 0, RMS, 1));
        assertNamed("frames", () -> RippleField.synthesize(32, 0, TILE, PERIOD, WIND, 0, RMS, 1));
        assertNamed("tileMetres", () -> RippleField.synthesize(32, 4, 0, PERIOD, WIND, 0, RMS, 1));
        assertNamed("periodSeconds", () -> RippleField.synthesize(32, 4, TILE, -1, WIND, 0, RMS, 1));
        assertNamed("windSpeed", () -> RippleField.synthesize(32, 4, TILE, PERIOD, Double.NaN, 0, RMS, 1));
        assertNamed("windDirectionDegrees",
                () -> RippleField.synthesize(32, 4, TILE, PERIOD, WIND, Double.POSITIVE_INFINITY, RMS, 1));
        assertNamed("rmsSlope", () -> RippleField.synthesize(32, 4, TILE, PERIOD, WIND, 0, 0, 1));
        // a breeze whose largest waves (V²/g = 0.1 mm) are far below the texels raises nothing to normalise
        assertNamed("windSpeed", () -> RippleField.synthesize(32, 4, 1000, PERIOD, 0.03, 0, RMS, 1));
        assertNamed("slopeScale", () -> field(8, 1, 0, 1).texels(0));
    }

    private static void assertNamed(String name, Runnable call) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, call::run);
        assertTrue(e.getMessage().startsWith(name + " "), "message names " + name + ": " + e.getMessage());
    }
}

package org.openworld.engine.water;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The ripples' waves in the frequency domain: dispersion, the loop, a real field, the empty mean and Nyquist waves. */
class RippleSpectrumTest {

    private static final int SIZE = 32;
    private static final double TILE = 8; // metres
    private static final double PERIOD = 20; // seconds

    private static RippleSpectrum spectrum(long seed) {
        return RippleSpectrum.of(SIZE, TILE, PERIOD, 6, 40, seed);
    }

    private static double[] at(RippleSpectrum s, double periods) {
        double[] out = new double[2 * SIZE * SIZE];
        s.at(periods, out);
        return out;
    }

    @Test
    void quantisedDispersionIsAWholeNumberOfCyclesPerPeriodJustBelowTheDeepWaterOne() {
        double omega0 = 2 * Math.PI / PERIOD;
        for (double k = 0.05; k < 200; k *= 1.37) {
            double cycles = RippleSpectrum.cyclesPerPeriod(k, PERIOD);
            assertEquals(Math.rint(cycles), cycles, "whole cycles per period at k = " + k);
            double omega = cycles * omega0;
            double exact = Math.sqrt(RippleSpectrum.GRAVITY * k);
            assertTrue(omega <= exact && omega > exact - omega0, "ω " + omega + " vs √(gk) " + exact);
        }
    }

    /** Whole periods give exactly the same coefficients: the phases are reduced to a fraction of a turn first. */
    @Test
    void wholePeriodsGiveTheSameCoefficientsBitForBit() {
        RippleSpectrum s = spectrum(1);
        double[] start = at(s, 0);
        assertArrayEquals(start, at(s, 1));
        assertArrayEquals(start, at(s, 3));
        double moved = 0;
        double[] half = at(s, 0.5);
        for (int i = 0; i < start.length; i++) {
            moved += Math.abs(half[i] - start[i]);
        }
        // 0.1 summed over all coefficients: any real motion is orders above it, a frozen spectrum gives 0 exactly
        assertTrue(moved > 0.1, "within the period the waves move: " + moved);
    }

    /** h(−k, t) = conj(h(k, t)) at every moment, so the heights and slopes the transforms make are real. */
    @Test
    void theCoefficientsAreConjugateSymmetric() {
        RippleSpectrum s = spectrum(2);
        for (double periods : new double[] {0, 0.17, 0.61}) {
            double[] h = at(s, periods);
            for (int r = 0; r < SIZE; r++) {
                for (int c = 0; c < SIZE; c++) {
                    int i = r * SIZE + c;
                    int j = ((SIZE - r) % SIZE) * SIZE + (SIZE - c) % SIZE;
                    // doubles: conjugate pairs built from the same numbers, equal to round-off
                    assertEquals(h[2 * i], h[2 * j], 1e-12, "real parts of k and −k");
                    assertEquals(h[2 * i + 1], -h[2 * j + 1], 1e-12, "imaginary parts of k and −k");
                }
            }
        }
    }

    /** Nothing in the mean level, nor on the Nyquist row and column (index size/2, frequency −size/2). */
    @Test
    void theMeanAndTheNyquistRowAndColumnAreEmpty() {
        double[] h = at(spectrum(3), 0.3);
        assertEquals(0, h[0]);
        assertEquals(0, h[1]);
        for (int j = 0; j < SIZE; j++) {
            int row = (SIZE / 2) * SIZE + j;
            int column = j * SIZE + SIZE / 2;
            double sum = Math.abs(h[2 * row]) + Math.abs(h[2 * row + 1]) + Math.abs(h[2 * column])
                    + Math.abs(h[2 * column + 1]);
            assertEquals(0, sum, "Nyquist row and column at index " + j);
        }
        assertTrue(Math.abs(h[2 * (SIZE + 1)]) + Math.abs(h[2 * (SIZE + 1) + 1]) > 0, "other waves are not empty");
    }

    /** The Parseval sum scales with the square of the amplitudes, as the field's rescaling to a slope assumes. */
    @Test
    void theMeanSquareSlopeGrowsWithTheSquareOfTheScale() {
        RippleSpectrum s = spectrum(4);
        double before = s.meanSquareSlope(4);
        s.scale(3);
        assertEquals(9 * before, s.meanSquareSlope(4), 1e-12 * before);
    }
}

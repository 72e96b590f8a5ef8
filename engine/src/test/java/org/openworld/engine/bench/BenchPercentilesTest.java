package org.openworld.engine.bench;

import org.junit.jupiter.api.Test;

import java.util.stream.IntStream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

class BenchPercentilesTest {

    private static final double EPS = 1e-9;

    /** 1..100, shuffled so sorting is tested too. */
    private static final Percentiles ONE_TO_HUNDRED = new Percentiles(
            IntStream.rangeClosed(1, 100).map(i -> (i * 37) % 100 + 1).asDoubleStream().toArray());

    @Test
    void linearInterpolationOnOneToHundred() {
        assertEquals(1.0, ONE_TO_HUNDRED.at(0), EPS);
        assertEquals(50.5, ONE_TO_HUNDRED.median(), EPS);
        assertEquals(95.05, ONE_TO_HUNDRED.at(95), EPS);
        assertEquals(99.01, ONE_TO_HUNDRED.at(99), EPS);
        assertEquals(100.0, ONE_TO_HUNDRED.at(100), EPS);
        assertEquals(100.0, ONE_TO_HUNDRED.max(), EPS);
        assertEquals(50.5, ONE_TO_HUNDRED.mean(), EPS);
    }

    @Test
    void oddCountMedianIsTheMiddleSample() {
        assertEquals(3.0, new Percentiles(new double[] {9, 1, 3}).median(), EPS);
    }

    @Test
    void singleSampleIsEveryPercentile() {
        Percentiles one = new Percentiles(new double[] {7});
        assertEquals(7.0, one.at(0), EPS);
        assertEquals(7.0, one.at(99), EPS);
    }

    @Test
    void rejectsNoSamplesAndPercentOutOfRange() {
        assertThrows(IllegalArgumentException.class, () -> new Percentiles(new double[0]));
        assertThrows(IllegalArgumentException.class, () -> ONE_TO_HUNDRED.at(101));
        assertThrows(IllegalArgumentException.class, () -> ONE_TO_HUNDRED.at(Double.NaN));
    }
}

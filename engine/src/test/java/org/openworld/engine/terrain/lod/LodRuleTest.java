package org.openworld.engine.terrain.lod;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class LodRuleTest {

    @ParameterizedTest(name = "L_B(D = {0} m) with B = {1} m is {2}")
    @CsvSource({
            // D < B: the formula goes negative; clamped to full resolution.
            "0, 100, 0",
            "50, 100, 0",
            "99.9, 100, 0",
            // B ≤ D < 2B: log2 in [0, 1).
            "100, 100, 0",
            "199.9, 100, 0",
            "200, 100, 1",
            "399, 100, 1",
            "400, 100, 2",
            "1000, 100, 3",
            "1600, 100, 4",
            "3199, 100, 4",
            "3200, 100, 5",
            "10, 2.5, 2",
            "1e6, 1, 19",
            "1048576, 1, 20"})
    void paperEquationTwo(double distance, double base, int expected) {
        assertEquals(expected, LodRule.level(distance, base));
        if (distance >= 2 * base) {
            assertEquals((int) Math.floor(Math.log(distance / base) / Math.log(2)), LodRule.level(distance, base),
                    "agrees with the formula written with logarithms");
        }
    }
}

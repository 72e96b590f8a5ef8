package org.openworld.engine.particles;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.openworld.engine.core.HeightField;

class GroundPatchTest {

    @Test
    void aPlaneIsReproducedExactlyBetweenTheSamples() {
        HeightField plane = (x, z) -> 12 + 0.25 * x - 0.5 * z;
        GroundPatch patch = GroundPatch.sample(plane, 100, -40, 64, 33);
        for (float x = 80; x <= 120; x += 1.37f) {
            for (float z = -60; z <= -20; z += 2.91f) {
                assertEquals(plane.heightAt(x, z), patch.heightAt(x, z), 1e-4, x + ", " + z);
            }
        }
    }

    @Test
    void bilinearBetweenSamplesAndTheEdgeBeyond() {
        HeightField bump = (x, z) -> x * z;
        GroundPatch patch = GroundPatch.sample(bump, 0, 0, 8, 5); // spacing 2, samples at -4 .. 4
        assertEquals(-4, patch.originX(), 0);
        assertEquals(2, patch.spacing(), 0);
        // float heights (24-bit mantissa): 1e-6 to 1e-5 on values of a few metres
        assertEquals(1 * 1, patch.heightAt(1, 1), 1e-6, "bilinear reproduces x z inside a cell");
        assertEquals(patch.heightAt(4, 4), patch.heightAt(9, 7), 0, "beyond the grid: the edge sample");
    }

    @Test
    void thePatchSitsOnItsSpacingSoResamplingKeepsTheSamePoints() {
        HeightField waves = (x, z) -> Math.sin(0.3 * x) * Math.cos(0.2 * z) * 10;
        GroundPatch a = GroundPatch.sample(waves, 10.3, 5.1, 40, 41);
        GroundPatch b = GroundPatch.sample(waves, 13.9, 7.7, 40, 41);
        for (float x = 5; x < 20; x += 0.7f) {
            assertEquals(a.heightAt(x, 8), b.heightAt(x, 8), 1e-5, "x " + x);
        }
    }

    @Test
    void coversTheSquareAroundAPointOnlyWithinItsGridAndForItsField() {
        HeightField flat = HeightField.FLAT;
        GroundPatch patch = GroundPatch.sample(flat, 0, 0, 80, 81);
        assertTrue(patch.covers(flat, 0, 0, 20));
        assertTrue(patch.covers(flat, 19, -19, 20));
        assertFalse(patch.covers(flat, 21, 0, 20), "the square pokes out of the grid");
        assertFalse(patch.covers((x, z) -> 1, 0, 0, 20), "another height field: sample again");
        assertThrows(IllegalArgumentException.class, () -> GroundPatch.sample(flat, 0, 0, 10, 1));
    }
}

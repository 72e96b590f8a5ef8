package org.openworld.engine.terrain.material;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.openworld.engine.terrain.heights.HeightMap;

/** The erosion's change as the materials read it: sediment cover in b, the bed kept in a. */
class ErosionCoverTest {

    @Test
    void noErosionCoversNothingAndBaresNothing() {
        byte[][] cover = ErosionCover.of(null, 8);
        for (int i = 0; i < 64; i++) {
            assertEquals(0, cover[0][i] & 0xFF);
            assertEquals(255, cover[1][i] & 0xFF, "a = 255: what the unbounded world's two-channel texture reads");
        }
    }

    /** A thick deposit covers, a deep cut bares, a thin change shows nothing; read between samples bilinearly. */
    @Test
    void thicknessSetsTheCover() {
        float thick = (float) ErosionCover.FULL_M;
        float thin = (float) ErosionCover.THIN_M / 2;
        HeightMap change = new HeightMap(2, 8, new float[] {thick, -thick, thin, -thin}, true);
        byte[][] cover = ErosionCover.of(change, 4); // each change sample at every second texel
        assertEquals(255, cover[0][0] & 0xFF, "3 m of sediment covers");
        assertEquals(255, cover[1][0] & 0xFF, "and bares nothing");
        assertEquals(0, cover[1][2] & 0xFF, "3 m cut away: bare");
        assertEquals(0, cover[0][2] & 0xFF, "and no sediment");
        assertEquals(0, cover[0][8] & 0xFF, "a quarter metre shows nothing");
        assertEquals(255, cover[1][8] & 0xFF);
        int between = cover[0][1] & 0xFF; // halfway from +3 m to -3 m: 0 m
        assertEquals(0, between, "the mean of a deposit and a cut is no change");
        assertTrue((cover[0][4] & 0xFF) > 0 && (cover[0][4] & 0xFF) < 255,
                "halfway from 3 m to 0.25 m: partly covered, " + (cover[0][4] & 0xFF));
    }
}

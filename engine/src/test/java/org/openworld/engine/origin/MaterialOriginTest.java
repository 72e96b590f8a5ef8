package org.openworld.engine.origin;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The lattices' offsets against the lattices themselves: for a world point w near a far origin o, the shader's sum
 * (small coordinates of w − o, in float, plus the origin's whole and fraction) must name the same lattice cell and
 * the same place in it as w's own coordinates, computed here in double, modulo the hash's period.
 */
class MaterialOriginTest {

    /** A far origin: 2442 tiles of 4096 m out on x, 1221 back on z. */
    static final double OX = 2442 * 4096.0;
    static final double OZ = -1221 * 4096.0;

    @Test
    void theSplitKeepsTheCoordinateModuloTheHashPeriod() {
        float[] out = new float[4];
        MaterialOrigin.split(83_353.6, -12_345.25, out, 0);
        assertEquals(3353, out[0]);
        assertEquals(7654, out[1], "floor(-12345.25) = -12346, which is 7654 modulo 10000");
        // float outputs (24-bit mantissa): 1e-6 on values under 1
        assertEquals(0.6, out[2], 1e-6);
        assertEquals(0.75, out[3], 1e-6);
    }

    @Test
    void theMacroOctavesLandOnTheWorldsCells() {
        float[] origin = MaterialOrigin.macro(OX, OZ);
        double[][] points = {{OX + 1000, OZ + 1000}, {OX - 1900.5, OZ + 37.25}, {OX + 30_000, OZ - 20_000}};
        for (double[] w : points) {
            for (int set = 0; set < 2; set++) {
                // the shader: p = (w − o) / scale (the tint: swapped, times 1.7), turned and doubled each octave
                float rx = (float) (w[0] - OX);
                float rz = (float) (w[1] - OZ);
                float px = (set == 0 ? rx : 1.7f * rz) / 120f;
                float py = (set == 0 ? rz : 1.7f * rx) / 120f;
                // the world: the same maps of w itself, in double
                double wx = (set == 0 ? w[0] : 1.7 * w[1]) / 120;
                double wy = (set == 0 ? w[1] : 1.7 * w[0]) / 120;
                for (int i = 0; i < 4; i++) {
                    int at = 4 * (4 * set + i);
                    float sx = px + origin[at + 2];
                    float sy = py + origin[at + 3];
                    double cellX = Math.floor(sx) + origin[at];
                    double cellY = Math.floor(sy) + origin[at + 1];
                    assertCell(wx, cellX, sx - Math.floor(sx), "octave " + i + " x of set " + set);
                    assertCell(wy, cellY, sy - Math.floor(sy), "octave " + i + " y of set " + set);
                    float nx = 2 * (0.8f * px - 0.6f * py);
                    float ny = 2 * (0.6f * px + 0.8f * py);
                    px = nx;
                    py = ny;
                    double mx = 2 * (0.8 * wx - 0.6 * wy);
                    double my = 2 * (0.6 * wx + 0.8 * wy);
                    wx = mx;
                    wy = my;
                }
            }
        }
    }

    @Test
    void theTilesLandOnTheWorldsTexels() {
        double scale = 2.7;
        float[] origin = MaterialOrigin.tiles(OX, OZ, scale);
        double wx = OX + 812.3;
        double wz = OZ - 97.1;
        // plane xz, fine tile: the texture repeats every unit, so the place in the tile is all that must agree
        float fine = (float) (wx - OX) / (float) scale + origin[2];
        double worldFine = wx / scale;
        // 1e-4 of a tile: the shader's float fractions of coordinates reduced near the origin (24-bit mantissa over a
        // few thousand tiles)
        assertEquals(worldFine - Math.floor(worldFine), fine - Math.floor(fine), 1e-4, "fine tile, x");
        // the coarse tile, turned: its u mixes x and z
        float fx = (float) (wx - OX) / (float) scale;
        float fz = (float) (wz - OZ) / (float) scale;
        float coarse = (0.8253f * fx - 0.5646f * fz) / 6.3f + origin[4 + 2];
        double worldCoarse = (0.8253 * wx / scale - 0.5646 * wz / scale) / 6.3;
        assertEquals(worldCoarse - Math.floor(worldCoarse), coarse - Math.floor(coarse), 1e-4, "coarse tile, u");
    }

    /**
     * The world's coordinate w and the shader's cell and place agree modulo the hash's period: within 1e-3 of a cell
     * (a float's error at a few thousand cells; a texel of a 512² tile is 2e-3).
     */
    private static void assertCell(double world, double cell, double place, String what) {
        double shader = cell + place;
        double difference = RenderOrigin.reduce(world - shader + 0.5, MaterialOrigin.HASH_PERIOD) - 0.5;
        // 1e-3 of a cell: float (as in the shader) against double; far from the origin, unreduced, it would be whole
        // cells
        assertTrue(Math.abs(difference) < 1e-3, what + ": the world at " + world + ", the shader at cell " + cell
                + " + " + place + " (" + difference + " cells apart)");
    }
}

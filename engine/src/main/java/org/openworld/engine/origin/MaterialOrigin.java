package org.openworld.engine.origin;

/**
 * Where the render origin lies on the terrain materials' lattices and tiles
 * ({@code shaders/terrain/material/material.glsl}): for each, the origin's coordinates on it, computed in double and split into a whole part, reduced modulo the hash's
 * period, and a fraction ({@link #split}). The shader adds the fraction to the point's own small coordinates and the
 * whole part to its cell, so a lattice point's hash and a tile's texel are those the world's coordinates give, with
 * no float ever larger than a few thousand cells. The maps are material.glsl's, restated here: a change there
 * must be made here too (the GL test at 2442 tiles out fails otherwise).
 */
public final class MaterialOrigin {

    /** Cells after which material.glsl's lattice hash repeats: 0.1031 times it is the whole number 1031. */
    public static final double HASH_PERIOD = 10_000;
    /** Metres: the wavelength of the macro noise's lowest octave (material.glsl's MAT_MACRO_SCALE). */
    static final double MACRO_SCALE = 120;
    /** The macro noise's turn between octaves, cos and sin of 37° (matMacro's {@code turn}, times 2 a step). */
    static final double MACRO_COS = 0.80;
    static final double MACRO_SIN = 0.60;
    /** The tint's lattices run 1.7 times finer, x and z swapped (matMacroTint). */
    static final double TINT_SCALE = 1.7;
    /** The coarse tile: 6.3 fine tiles, turned by 0.6 rad (MAT_COARSE_FACTOR, matCoords's {@code turn}). */
    static final double COARSE_FACTOR = 6.3;
    static final double COARSE_COS = 0.8253;
    static final double COARSE_SIN = 0.5646;

    private MaterialOrigin() {
    }

    /**
     * {@code uMatMacroOrigin}: 8 vec4s (whole x, whole y, fraction x, fraction y), the lattices of matMacro's four
     * octaves for the brightness, then the tint's. Octave i's lattice point of a world point w is
     * {@code M_i w / MACRO_SCALE + c_i} with {@code M_0 = I} (the tint: the swap times TINT_SCALE) and
     * {@code M_{i+1} = 2 · turn · M_i}; the shader keeps the constants c_i, so the origin's share is {@code M_i o}.
     */
    public static float[] macro(double originX, double originZ) {
        float[] out = new float[8 * 4];
        for (int set = 0; set < 2; set++) {
            double x = set == 0 ? originX : TINT_SCALE * originZ;
            double y = set == 0 ? originZ : TINT_SCALE * originX;
            x /= MACRO_SCALE;
            y /= MACRO_SCALE;
            for (int i = 0; i < 4; i++) {
                split(x, y, out, 4 * (4 * set + i));
                // GLSL's mat2(0.80, 0.60, -0.60, 0.80) has columns (0.8, 0.6) and (-0.6, 0.8)
                double nx = 2 * (MACRO_COS * x - MACRO_SIN * y);
                double ny = 2 * (MACRO_SIN * x + MACRO_COS * y);
                x = nx;
                y = ny;
            }
        }
        return out;
    }

    /**
     * {@code uMatTileOrigin}: 6 vec4s, the fine and the coarse tile's coordinates of the origin in the planes xz, zy
     * and xy (y is 0 at the origin), {@code detailScale} metres per fine tile.
     */
    public static float[] tiles(double originX, double originZ, double detailScale) {
        float[] out = new float[6 * 4];
        double[][] planes = {{originX, originZ}, {originZ, 0}, {originX, 0}};
        for (int plane = 0; plane < 3; plane++) {
            double u = planes[plane][0] / detailScale;
            double v = planes[plane][1] / detailScale;
            split(u, v, out, 4 * (2 * plane));
            split((COARSE_COS * u - COARSE_SIN * v) / COARSE_FACTOR, (COARSE_SIN * u + COARSE_COS * v) / COARSE_FACTOR,
                    out, 4 * (2 * plane + 1));
        }
        return out;
    }

    /**
     * A lattice coordinate (x, y) as (whole x, whole y, fraction x, fraction y) at {@code out[at..at+3]}: the whole
     * parts reduced modulo {@link #HASH_PERIOD} (whole numbers below 10000, exact in a float), the fractions in
     * [0, 1).
     */
    static void split(double x, double y, float[] out, int at) {
        double wx = Math.floor(x);
        double wy = Math.floor(y);
        out[at] = (float) RenderOrigin.reduce(wx, HASH_PERIOD);
        out[at + 1] = (float) RenderOrigin.reduce(wy, HASH_PERIOD);
        out[at + 2] = (float) (x - wx);
        out[at + 3] = (float) (y - wy);
    }
}

package org.openworld.engine.colour;

/**
 * A colour in CIELAB (CIE 1976 L*a*b*): {@code l} lightness, 0 black to 100 the white point; {@code a} green (−) to
 * red (+); {@code b} blue (−) to yellow (+). Distances in this space follow perceived differences far better than
 * distances in RGB.
 *
 * <p>{@link #fromSrgb} decodes 8-bit sRGB (IEC 61966-2-1) to linear light, converts it to CIE XYZ with the sRGB
 * primaries, and then to L*a*b* relative to the D65 white that sRGB is defined for, so sRGB white is L* = 100,
 * a* = b* = 0, and every grey has a* = b* = 0. The decoding goes through a 256-entry table, so a conversion costs
 * three matrix rows and three cube roots.
 */
public record Lab(double l, double a, double b) {

    /** Linear sRGB to CIE XYZ: the sRGB primaries and D65 white (IEC 61966-2-1), one row per X, Y, Z. */
    private static final double[][] TO_XYZ = {
        {0.4124564, 0.3575761, 0.1804375},
        {0.2126729, 0.7151522, 0.0721750},
        {0.0193339, 0.1191920, 0.9503041},
    };

    /**
     * The D65 white point in XYZ (0.95047, 1, 1.08883 to seven digits), taken as the rows' sums, the XYZ of sRGB
     * white, so that every sRGB grey has a* = b* = 0 exactly and white has L* = 100.
     */
    private static final double WHITE_X = rowSum(0);
    private static final double WHITE_Y = rowSum(1);
    private static final double WHITE_Z = rowSum(2);

    /** CIELAB's switch from the cube root to a line near black: (6/29)^3, so f is continuous with its slope. */
    private static final double EPSILON = Math.pow(6.0 / 29.0, 3);
    private static final double LINEAR_SLOPE = 1.0 / (3 * Math.pow(6.0 / 29.0, 2));
    private static final double LINEAR_OFFSET = 4.0 / 29.0;

    /** Linear light for each 8-bit sRGB code value. */
    private static final double[] LINEAR = new double[256];

    static {
        for (int i = 0; i < 256; i++) {
            double c = i / 255.0;
            LINEAR[i] = c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
        }
    }

    /** The colour of 8-bit sRGB code values r, g, b (each 0–255). */
    public static Lab fromSrgb(int r, int g, int b) {
        double lr = LINEAR[r];
        double lg = LINEAR[g];
        double lb = LINEAR[b];
        double fx = f(xyz(0, lr, lg, lb) / WHITE_X);
        double fy = f(xyz(1, lr, lg, lb) / WHITE_Y);
        double fz = f(xyz(2, lr, lg, lb) / WHITE_Z);
        return new Lab(116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz));
    }

    /** Linear light (0 to 1) of an 8-bit sRGB code value. */
    public static double linear(int code) {
        return LINEAR[code];
    }

    private static double xyz(int row, double r, double g, double b) {
        return TO_XYZ[row][0] * r + TO_XYZ[row][1] * g + TO_XYZ[row][2] * b;
    }

    private static double rowSum(int row) {
        return xyz(row, 1, 1, 1);
    }

    private static double f(double t) {
        return t > EPSILON ? Math.cbrt(t) : t * LINEAR_SLOPE + LINEAR_OFFSET;
    }
}

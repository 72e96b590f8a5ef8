package org.openworld.engine.sky;

import org.joml.Matrix3d;
import org.joml.Vector3d;

/**
 * The wavelengths the sky is computed at, and the conversion of a sampled spectrum to linear sRGB (paper 3.1: "the
 * scattering equations are highly non-linear, and the colors do not blend additively", so the sky is solved per
 * wavelength and only then combined with a tristimulus model).
 * <p>
 * Sampling: {@code count} wavelengths by the midpoint rule over [400, 750] nm, λ_i = 400 + (i + ½)·350/count, each
 * standing for a band Δλ = 350/count nm wide.
 * <p>
 * Conversion ({@link #toRgb}): XYZ = Σ_i L_i·(x̄, ȳ, z̄)(λ_i)·Δλ with the CIE 1931 2° colour matching functions, then
 * a chromatic adaptation from the white this sampling makes of an equal-energy spectrum (illuminant E, the colour
 * of our sun above the atmosphere) to D65 with the Bradford cone matrix, then the XYZ → linear sRGB matrix
 * (IEC 61966-2-1), then a last per-channel scale (a correction of order 10⁻⁴, the rounding of the published
 * matrices) so that a flat spectrum of value v gives exactly (v, v, v). So the sun above the atmosphere is white,
 * and a flat spectral value 1 is display value 1.
 */
public final class Spectrum {

    /** Shortest wavelength sampled, nm: the blue end of what the eye sees (the paper's range). */
    public static final double MIN_NM = 400;
    /** Longest wavelength sampled, nm: the red end of the paper's range; ȳ is below 1.2·10⁻⁴ beyond it. */
    public static final double MAX_NM = 750;

    /** First wavelength of {@link #CMF}, nm. */
    private static final double CMF_FIRST_NM = 360;
    /** Step of {@link #CMF}, nm. */
    private static final double CMF_STEP_NM = 5;
    /**
     * CIE 1931 2° standard observer x̄, ȳ, z̄ at 360, 365, ... 830 nm (CIE 15:2004 table, as distributed by CVRL,
     * "ciexyz31"), three values per row.
     */
    private static final double[] CMF = {
            0.0001299, 3.917e-06, 0.0006061, // 360
            0.0002321, 6.965e-06, 0.001086, // 365
            0.0004149, 1.239e-05, 0.001946, // 370
            0.0007416, 2.202e-05, 0.003486, // 375
            0.001368, 3.9e-05, 0.006450001, // 380
            0.002236, 6.4e-05, 0.01054999, // 385
            0.004243, 0.00012, 0.02005001, // 390
            0.00765, 0.000217, 0.03621, // 395
            0.01431, 0.000396, 0.06785001, // 400
            0.02319, 0.00064, 0.1102, // 405
            0.04351, 0.00121, 0.2074, // 410
            0.07763, 0.00218, 0.3713, // 415
            0.13438, 0.004, 0.6456, // 420
            0.21477, 0.0073, 1.0390501, // 425
            0.2839, 0.0116, 1.3856, // 430
            0.3285, 0.01684, 1.62296, // 435
            0.34828, 0.023, 1.74706, // 440
            0.34806, 0.0298, 1.7826, // 445
            0.3362, 0.038, 1.77211, // 450
            0.3187, 0.048, 1.7441, // 455
            0.2908, 0.06, 1.6692, // 460
            0.2511, 0.0739, 1.5281, // 465
            0.19536, 0.09098, 1.28764, // 470
            0.1421, 0.1126, 1.0419, // 475
            0.09564, 0.13902, 0.8129501, // 480
            0.05795001, 0.1693, 0.6162, // 485
            0.03201, 0.20802, 0.46518, // 490
            0.0147, 0.2586, 0.3533, // 495
            0.0049, 0.323, 0.272, // 500
            0.0024, 0.4073, 0.2123, // 505
            0.0093, 0.503, 0.1582, // 510
            0.0291, 0.6082, 0.1117, // 515
            0.06327, 0.71, 0.07824999, // 520
            0.1096, 0.7932, 0.05725001, // 525
            0.1655, 0.862, 0.04216, // 530
            0.2257499, 0.9148501, 0.02984, // 535
            0.2904, 0.954, 0.0203, // 540
            0.3597, 0.9803, 0.0134, // 545
            0.4334499, 0.9949501, 0.008749999, // 550
            0.5120501, 1.0, 0.005749999, // 555
            0.5945, 0.995, 0.0039, // 560
            0.6784, 0.9786, 0.002749999, // 565
            0.7621, 0.952, 0.0021, // 570
            0.8425, 0.9154, 0.0018, // 575
            0.9163, 0.87, 0.001650001, // 580
            0.9786, 0.8163, 0.0014, // 585
            1.0263, 0.757, 0.0011, // 590
            1.0567, 0.6949, 0.001, // 595
            1.0622, 0.631, 0.0008, // 600
            1.0456, 0.5668, 0.0006, // 605
            1.0026, 0.503, 0.00034, // 610
            0.9384, 0.4412, 0.00024, // 615
            0.8544499, 0.381, 0.00019, // 620
            0.7514, 0.321, 0.0001, // 625
            0.6424, 0.265, 4.999999e-05, // 630
            0.5419, 0.217, 3e-05, // 635
            0.4479, 0.175, 2e-05, // 640
            0.3608, 0.1382, 1e-05, // 645
            0.2835, 0.107, 0.0, // 650
            0.2187, 0.0816, 0.0, // 655
            0.1649, 0.061, 0.0, // 660
            0.1212, 0.04458, 0.0, // 665
            0.0874, 0.032, 0.0, // 670
            0.0636, 0.0232, 0.0, // 675
            0.04677, 0.017, 0.0, // 680
            0.0329, 0.01192, 0.0, // 685
            0.0227, 0.00821, 0.0, // 690
            0.01584, 0.005723, 0.0, // 695
            0.01135916, 0.004102, 0.0, // 700
            0.008110916, 0.002929, 0.0, // 705
            0.005790346, 0.002091, 0.0, // 710
            0.004109457, 0.001484, 0.0, // 715
            0.002899327, 0.001047, 0.0, // 720
            0.00204919, 0.00074, 0.0, // 725
            0.001439971, 0.00052, 0.0, // 730
            0.0009999493, 0.0003611, 0.0, // 735
            0.0006900786, 0.0002492, 0.0, // 740
            0.0004760213, 0.0001719, 0.0, // 745
            0.0003323011, 0.00012, 0.0, // 750
            0.0002348261, 8.48e-05, 0.0, // 755
            0.0001661505, 6e-05, 0.0, // 760
            0.000117413, 4.24e-05, 0.0, // 765
            8.307527e-05, 3e-05, 0.0, // 770
            5.870652e-05, 2.12e-05, 0.0, // 775
            4.150994e-05, 1.499e-05, 0.0, // 780
            2.935326e-05, 1.06e-05, 0.0, // 785
            2.067383e-05, 7.4657e-06, 0.0, // 790
            1.455977e-05, 5.2578e-06, 0.0, // 795
            1.025398e-05, 3.7029e-06, 0.0, // 800
            7.221456e-06, 2.6078e-06, 0.0, // 805
            5.085868e-06, 1.8366e-06, 0.0, // 810
            3.581652e-06, 1.2934e-06, 0.0, // 815
            2.522525e-06, 9.1093e-07, 0.0, // 820
            1.776509e-06, 6.4153e-07, 0.0, // 825
            1.251141e-06, 4.5181e-07, 0.0, // 830
    };

    /** Bradford cone response matrix, rows (Lindbloom, "Chromatic Adaptation"). */
    private static final Matrix3d BRADFORD = rows(
            0.8951, 0.2664, -0.1614,
            -0.7502, 1.7135, 0.0367,
            0.0389, -0.0685, 1.0296);
    /** XYZ → linear sRGB, rows (IEC 61966-2-1, D65 white). */
    private static final Matrix3d XYZ_TO_SRGB = rows(
            3.2404542, -1.5371385, -0.4985314,
            -0.9692660, 1.8760108, 0.0415560,
            0.0556434, -0.2040259, 1.0572252);
    /** D65 white point, XYZ with Y = 1. */
    private static final Vector3d D65 = new Vector3d(0.95047, 1.0, 1.08883);

    private final double[] wavelengths;
    /** Per sample, x̄ȳz̄·Δλ, three values each. */
    private final double[] weights;
    /** XYZ → white-balanced linear sRGB for this sampling. */
    private final Matrix3d xyzToRgb;

    private Spectrum(int count) {
        if (count < 1) {
            throw new IllegalArgumentException("a spectrum needs at least one wavelength, got " + count);
        }
        double bandNm = (MAX_NM - MIN_NM) / count;
        wavelengths = new double[count];
        weights = new double[3 * count];
        Vector3d white = new Vector3d();
        for (int i = 0; i < count; i++) {
            wavelengths[i] = MIN_NM + (i + 0.5) * bandNm;
            double[] cmf = colourMatching(wavelengths[i]);
            for (int c = 0; c < 3; c++) {
                weights[3 * i + c] = cmf[c] * bandNm;
            }
            white.add(weights[3 * i], weights[3 * i + 1], weights[3 * i + 2]);
        }
        // Bradford: adapt the sampled equal-energy white to D65 (Y = 1) in cone space.
        Vector3d coneSource = BRADFORD.transform(new Vector3d(white));
        Vector3d coneTarget = BRADFORD.transform(new Vector3d(D65));
        Matrix3d gain = new Matrix3d().scaling(coneTarget.x / coneSource.x, coneTarget.y / coneSource.y,
                coneTarget.z / coneSource.z);
        Matrix3d adapt = new Matrix3d(BRADFORD).invert().mul(gain).mul(BRADFORD);
        Matrix3d toRgb = new Matrix3d(XYZ_TO_SRGB).mul(adapt);
        // Remove the residual of the 4–7 digit published matrices so the flat spectrum is exactly neutral.
        Vector3d rgbWhite = toRgb.transform(new Vector3d(white));
        xyzToRgb = new Matrix3d().scaling(1 / rgbWhite.x, 1 / rgbWhite.y, 1 / rgbWhite.z).mul(toRgb);
    }

    /** {@code count} wavelengths by the midpoint rule over [{@value #MIN_NM}, {@value #MAX_NM}] nm. */
    public static Spectrum sampled(int count) {
        return new Spectrum(count);
    }

    /** Number of wavelengths. */
    public int count() {
        return wavelengths.length;
    }

    /** Wavelength of sample i, nm. */
    public double wavelengthNm(int i) {
        return wavelengths[i];
    }

    /**
     * CIE 1931 2° colour matching functions {x̄, ȳ, z̄} at a wavelength, linearly interpolated in the 5 nm table;
     * 0 outside 360–830 nm.
     */
    public static double[] colourMatching(double nm) {
        double position = (nm - CMF_FIRST_NM) / CMF_STEP_NM;
        int rows = CMF.length / 3;
        if (!(position >= 0 && position <= rows - 1)) {
            return new double[3];
        }
        int row = Math.min((int) position, rows - 2);
        double f = position - row;
        double[] out = new double[3];
        for (int c = 0; c < 3; c++) {
            out[c] = CMF[3 * row + c] * (1 - f) + CMF[3 * (row + 1) + c] * f;
        }
        return out;
    }

    /**
     * Linear sRGB of a sampled spectrum (one value per wavelength, in units of the flat solar spectrum), white
     * balanced so a flat spectrum of value v gives (v, v, v); see the class comment.
     */
    public Vector3d toRgb(double[] spectral, Vector3d out) {
        if (spectral.length != wavelengths.length) {
            throw new IllegalArgumentException("expected " + wavelengths.length + " spectral values, got "
                    + spectral.length);
        }
        double x = 0;
        double y = 0;
        double z = 0;
        for (int i = 0; i < spectral.length; i++) {
            x += spectral[i] * weights[3 * i];
            y += spectral[i] * weights[3 * i + 1];
            z += spectral[i] * weights[3 * i + 2];
        }
        return xyzToRgb.transform(out.set(x, y, z));
    }

    /**
     * {@link #toRgb} clipped to the sRGB gamut from below: the saturated oranges of twilight lie outside it and come
     * out with a slightly negative blue, which is set to 0 so a texture never holds negative light.
     */
    public Vector3d toDisplayRgb(double[] spectral, Vector3d out) {
        toRgb(spectral, out);
        return out.set(Math.max(out.x, 0), Math.max(out.y, 0), Math.max(out.z, 0));
    }

    /** Builds a JOML matrix (column-major) from values written row by row. */
    private static Matrix3d rows(double a, double b, double c, double d, double e, double f, double g, double h,
                                 double i) {
        return new Matrix3d(a, d, g, b, e, h, c, f, i);
    }
}

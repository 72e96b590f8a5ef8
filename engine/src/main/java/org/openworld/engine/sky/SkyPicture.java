package org.openworld.engine.sky;

import java.util.stream.IntStream;
import org.joml.Vector3d;
import org.openworld.engine.gl.Image;

/**
 * A picture of the sky alone computed on the CPU by {@link SkyReference}'s integrator, for checking the paper's
 * findings on sampling (3.1: at least 6 wavelengths, at least 2 samples in each sum) without OpenGL: skies made
 * with different {@link AtmosphereSettings} are shown the way the screen shows them and compared in CIEDE2000.
 * <p>
 * Framing: {@value #WIDTH} × {@value #HEIGHT} pixels, the half of the upper dome centred on the sun's azimuth,
 * azimuth −90° .. +90° from the sun left to right, elevation 90° (top) down to 0° (bottom), equal angles per pixel;
 * the eye {@value #EYE_ALTITUDE_M} m up. Display: the scene's own last steps ({@code shaders/common/color.glsl}):
 * times a fixed exposure per {@link Sun} (figure 9's, as {@code sky.auto-exposure=off}, so every picture of one sun
 * is shown alike and only the sampling differs), the ACES fit (Narkowicz 2015), the exact sRGB encoding, 8 bits.
 * The sun's disc is not drawn: only the scattered light. Two pictures are compared by their mean CIEDE2000
 * difference over all pixels ({@link org.openworld.engine.colour.ImageComparison}); 2 is about where a difference
 * becomes noticeable.
 * <p>
 * Cost: one {@link SkyIntegrator#dome} per pixel, 18 432 of them: 0.4–1.7 s for the default sums on 2 cores,
 * about 2 s with 64 samples in each sum.
 */
public final class SkyPicture {

    /** Picture size, pixels: about 1° per pixel (180° of azimuth over 192, 90° of elevation over 96). */
    public static final int WIDTH = 192;
    public static final int HEIGHT = 96;
    /** The wavelengths of the reference the spectral sampling is measured against: 4 times the default. */
    public static final int REFERENCE_WAVELENGTHS = 32;
    /**
     * The samples in each sum of the reference the single-scattering sums are measured against: the setting's
     * most. It is itself 0.17 (noon) and 0.14 (sunset) mean ΔE00 from 256 samples in each sum.
     */
    public static final int REFERENCE_SAMPLES = 64;
    /** The eye's altitude, m: the figures' starting pose, 400 m up. */
    public static final double EYE_ALTITUDE_M = 400;
    /** Half the azimuth range either side of the sun, radians. */
    private static final double HALF_AZIMUTH = Math.PI / 2;

    /**
     * A sun the findings are checked under, and the exposure it is shown with.
     *
     * @param name         in words, for labels
     * @param elevationDeg the sun's elevation, degrees
     * @param exposureEv   stops above noon's exposure (figure 9's {@code sky.exposure} for that light)
     */
    public record Sun(String name, double elevationDeg, double exposureEv) {
        /** Noon at the default latitude (46°) and declination (10°): the sun 54° up. */
        public static final Sun NOON = new Sun("noon", 54, 0);
        /** Sunset: the sun 1° up, figure 9e. */
        public static final Sun SUNSET = new Sun("sunset", 1, 3);
    }

    private SkyPicture() {
    }

    /** The sky for {@code settings} under {@code sun}, {@value #WIDTH} × {@value #HEIGHT} pixels. */
    public static Image render(AtmosphereSettings settings, Sun sun) {
        AtmosphereTables tables = AtmosphereTables.build(settings);
        double sunElevation = Math.toRadians(sun.elevationDeg());
        double exposure = Math.pow(2, sun.exposureEv());
        int width = WIDTH;
        int height = HEIGHT;
        byte[] rgba = new byte[width * height * 4];
        IntStream.range(0, height).parallel().forEach(y -> {
            SkyIntegrator integrator = new SkyIntegrator(tables);
            double[] spectral = new double[tables.spectrum().count()];
            Vector3d rgb = new Vector3d();
            double elevation = Math.PI / 2 * (1 - (y + 0.5) / height);
            for (int x = 0; x < width; x++) {
                double azimuth = Math.abs(HALF_AZIMUTH * (2 * (x + 0.5) / width - 1));
                integrator.dome(EYE_ALTITUDE_M, azimuth, elevation, sunElevation, spectral);
                tables.spectrum().toDisplayRgb(spectral, rgb).mul(exposure);
                int i = 4 * (y * width + x);
                rgba[i] = display(rgb.x);
                rgba[i + 1] = display(rgb.y);
                rgba[i + 2] = display(rgb.z);
                rgba[i + 3] = (byte) 255;
            }
        });
        return new Image(width, height, rgba);
    }

    /** Exposed linear light to an 8-bit code: the ACES fit, then the sRGB encoding, as the scene's shaders do. */
    static byte display(double linear) {
        double aces = Math.min(Math.max(
                linear * (2.51 * linear + 0.03) / (linear * (2.43 * linear + 0.59) + 0.14), 0), 1);
        double encoded = aces <= 0.0031308 ? 12.92 * aces : 1.055 * Math.pow(aces, 1 / 2.4) - 0.055;
        return (byte) Math.round(encoded * 255);
    }
}

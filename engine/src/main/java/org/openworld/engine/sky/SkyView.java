package org.openworld.engine.sky;

import java.util.stream.IntStream;

import org.joml.Vector3d;

/**
 * The sky dome for one sun position and eye altitude (Hillaire 2020 section 5.3, the "sky-view LUT"): one texel per
 * view direction, holding the radiance scattered toward the eye in display units (π·L / E_sun) as linear sRGB.
 * <p>
 * Layout: {@value #WIDTH} × {@value #HEIGHT} texels, row-major with v rows ({@code rgb[(y·WIDTH + x)·3 + c]}).
 * u = φ/π is the azimuth from the sun's vertical plane over [0, π] only, since the sky is symmetric about that
 * plane; v is the elevation e ∈ [−π/2, π/2] with Hillaire's non-linear mapping
 * <pre>
 *   v = ½ + ½·sign(e)·√(|e| / (π/2))        e = sign(v − ½)·(π/2)·(2v − 1)²
 * </pre>
 * which crowds texels at the horizon, where the sky changes fastest. Texel x holds u = x / (WIDTH − 1) and texel y
 * holds v = y / (HEIGHT − 1), so u, v ∈ [0, 1] reach texel centres with tex = ½/N + u·(1 − 1/N)
 * ({@code shaders/sky/atmosphere.glsl}). Each texel runs {@link SkyIntegrator#dome} once (in parallel over rows;
 * the result does not depend on the thread count) and is converted with {@link Spectrum#toDisplayRgb}, which clips
 * the few twilight oranges outside the sRGB gamut to it.
 */
public final class SkyView {

    /** Texels over the azimuth from the sun, 0..π (Hillaire's 192). */
    public static final int WIDTH = 192;
    /** Texels over the elevation, −90°..+90° (Hillaire's 108). */
    public static final int HEIGHT = 108;

    private final float[] rgb;
    private final double buildMillis;

    private SkyView(float[] rgb, double buildMillis) {
        this.rgb = rgb;
        this.buildMillis = buildMillis;
    }

    /** Computes every texel for a sun at {@code sunElevationRad} seen from {@code cameraAltitudeM} above the ground. */
    public static SkyView build(AtmosphereTables t, double sunElevationRad, double cameraAltitudeM) {
        long start = System.nanoTime();
        float[] rgb = new float[WIDTH * HEIGHT * 3];
        IntStream.range(0, HEIGHT).parallel().forEach(y -> {
            SkyIntegrator integrator = new SkyIntegrator(t);
            double[] spectral = new double[t.spectrum().count()];
            Vector3d colour = new Vector3d();
            double elevation = elevation(y / (HEIGHT - 1.0));
            for (int x = 0; x < WIDTH; x++) {
                double azimuth = Math.PI * x / (WIDTH - 1.0);
                integrator.dome(cameraAltitudeM, azimuth, elevation, sunElevationRad, spectral);
                t.spectrum().toDisplayRgb(spectral, colour);
                int i = (y * WIDTH + x) * 3;
                rgb[i] = (float) colour.x;
                rgb[i + 1] = (float) colour.y;
                rgb[i + 2] = (float) colour.z;
            }
        });
        return new SkyView(rgb, (System.nanoTime() - start) / 1e6);
    }

    /** Texel values, linear sRGB in display units, {@code (y·WIDTH + x)·3 + channel}. */
    public float[] rgb() {
        return rgb;
    }

    /** Wall-clock time of {@link #build}, ms. */
    public double buildMillis() {
        return buildMillis;
    }

    /**
     * Unit table coordinates {u, v} ∈ [0, 1]² of a direction: any azimuth is folded into [0, π] (the sky is
     * symmetric about the sun's vertical plane).
     */
    public static double[] uv(double azimuthFromSunRad, double elevationRad) {
        double folded = Math.abs(Math.IEEEremainder(azimuthFromSunRad, 2 * Math.PI));
        double e = TransmittanceTable.clamp(elevationRad, -Math.PI / 2, Math.PI / 2);
        double v = 0.5 + 0.5 * Math.signum(e) * Math.sqrt(Math.abs(e) / (Math.PI / 2));
        return new double[] {folded / Math.PI, v};
    }

    /** Inverse of {@link #uv}: {azimuth from the sun ∈ [0, π], elevation}, radians. */
    public static double[] direction(double u, double v) {
        return new double[] {u * Math.PI, elevation(v)};
    }

    /** Elevation of table coordinate v, radians. */
    static double elevation(double v) {
        double s = 2 * v - 1;
        return Math.signum(s) * (Math.PI / 2) * s * s;
    }

    /** The table bilinearly interpolated between texel centres at a direction, as a GPU sampler would. */
    public Vector3d sample(double azimuthFromSunRad, double elevationRad, Vector3d out) {
        double[] uv = uv(azimuthFromSunRad, elevationRad);
        return sampleUv(uv[0], uv[1], out);
    }

    /** The table bilinearly interpolated at unit coordinates (u, v). */
    Vector3d sampleUv(double u, double v, Vector3d out) {
        double fx = TransmittanceTable.clamp(u, 0, 1) * (WIDTH - 1);
        double fy = TransmittanceTable.clamp(v, 0, 1) * (HEIGHT - 1);
        int x0 = Math.min((int) fx, WIDTH - 2);
        int y0 = Math.min((int) fy, HEIGHT - 2);
        double ax = fx - x0;
        double ay = fy - y0;
        double[] c = new double[3];
        for (int ch = 0; ch < 3; ch++) {
            double bottom = texel(x0, y0, ch) * (1 - ax) + texel(x0 + 1, y0, ch) * ax;
            double top = texel(x0, y0 + 1, ch) * (1 - ax) + texel(x0 + 1, y0 + 1, ch) * ax;
            c[ch] = bottom + (top - bottom) * ay;
        }
        return out.set(c[0], c[1], c[2]);
    }

    /** One channel of texel (x, y). */
    double texel(int x, int y, int channel) {
        return rgb[(y * WIDTH + x) * 3 + channel];
    }
}

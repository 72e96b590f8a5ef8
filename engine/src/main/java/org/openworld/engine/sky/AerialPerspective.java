package org.openworld.engine.sky;

import java.util.stream.IntStream;

import org.joml.Vector3d;
import org.joml.Vector4d;

/**
 * The air between the eye and the terrain (Hillaire 2020 section 5.4, the "aerial perspective" volume): for each view
 * direction and distance, the light scattered toward the eye on the way and the transmittance of the way, so a
 * surface at distance d is seen as {@code surface·T + inscatter}.
 * <p>
 * Layout: {@value #WIDTH} (azimuth from the sun, 0..π) × {@value #HEIGHT} (elevation, {@link SkyView}'s non-linear
 * mapping) × {@value #DEPTH} distance slices, {@code rgba[((z·HEIGHT + y)·WIDTH + x)·4 + c]}. Slice k ends at
 * d_k = {@value #MAX_DISTANCE}·((k + 1)/{@value #DEPTH})² m, so near slices are thin where the eye sees detail,
 * and w = √(d / MAX_DISTANCE) = (k + 1)/DEPTH is linear in the slice index. A texel holds the in-scattered radiance
 * from the eye to d_k in display units (π·L / E_sun, linear sRGB) and the mean of the RGB transmittance over the
 * three channels. Before the first slice the shader fades from (0, 0, 0, 1) at d = 0.
 * <p>
 * {@link AtmosphereSettings#fog()} chooses what fills it:
 * <ul>
 * <li>{@code AERIAL}: one ray per direction is marched slice after slice with {@value #STEPS_PER_SLICE} steps each,
 *     in the scattering mode and component of the settings ({@link SkyIntegrator}); beyond the ground or the top of
 *     the atmosphere the slices repeat the last value.</li>
 * <li>{@code SIMPLE}: the paper's distance fog (section 1's "simple fog effect"), OpenGL's classic exponential fog:
 *     T = e^(−d/D) with D = {@link AtmosphereSettings#fogDistance()}, grey, and in-scattered light
 *     C_fog·(1 − T), so a surface fades as {@code c·T + C_fog·(1 − T)}. The paper gives neither the formula nor
 *     the colour; the fog colour C_fog here is the sky's own horizon (elevation 0 in the {@link SkyView}) at each
 *     azimuth from the sun, so distant ground fades into the sky behind it, orange towards a low sun and blue away
 *     from it. It ignores altitude and elevation: the fog is as thick looking down as looking along the ground.
 *     Same table, same shader, no marching.</li>
 * </ul>
 */
public final class AerialPerspective {

    /** Texels over the azimuth from the sun (Hillaire's 32). */
    public static final int WIDTH = 32;
    /** Texels over the elevation. */
    public static final int HEIGHT = 32;
    /** Distance slices. */
    public static final int DEPTH = 32;
    /** End of the last slice, m: beyond 64 km the terrain is out of view and the sky table takes over. */
    public static final double MAX_DISTANCE = 64_000;
    /** Steps per slice: two keep the longest slice (4 km) within 1 % of a fine march. */
    private static final int STEPS_PER_SLICE = 2;

    private final float[] rgba;
    private final double buildMillis;

    private AerialPerspective(float[] rgba, double buildMillis) {
        this.rgba = rgba;
        this.buildMillis = buildMillis;
    }

    /**
     * Fills the volume for a sun at {@code sunElevationRad} as the settings' fog asks: the scattering marched
     * ({@code AERIAL}) or the paper's distance fog towards {@code view}'s horizon ({@code SIMPLE}).
     */
    public static AerialPerspective build(AtmosphereTables t, SkyView view, double sunElevationRad,
                                          double cameraAltitudeM) {
        return t.settings().fog() == AtmosphereSettings.Fog.SIMPLE
                ? simpleFog(view, t.settings().fogDistance())
                : scattered(t, sunElevationRad, cameraAltitudeM);
    }

    /** The paper's fog: T = e^(−d/D) and the horizon colour of each azimuth times 1 − T, every elevation alike. */
    static AerialPerspective simpleFog(SkyView view, double fogDistanceM) {
        long start = System.nanoTime();
        float[] rgba = new float[WIDTH * HEIGHT * DEPTH * 4];
        Vector3d horizon = new Vector3d();
        for (int x = 0; x < WIDTH; x++) {
            view.sample(Math.PI * x / (WIDTH - 1.0), 0, horizon);
            for (int z = 0; z < DEPTH; z++) {
                double transmittance = Math.exp(-sliceEnd(z) / fogDistanceM);
                for (int y = 0; y < HEIGHT; y++) {
                    int i = (((z * HEIGHT) + y) * WIDTH + x) * 4;
                    rgba[i] = (float) (horizon.x * (1 - transmittance));
                    rgba[i + 1] = (float) (horizon.y * (1 - transmittance));
                    rgba[i + 2] = (float) (horizon.z * (1 - transmittance));
                    rgba[i + 3] = (float) transmittance;
                }
            }
        }
        return new AerialPerspective(rgba, (System.nanoTime() - start) / 1e6);
    }

    /** Marches every direction of the volume for a sun at {@code sunElevationRad}, rows in parallel. */
    static AerialPerspective scattered(AtmosphereTables t, double sunElevationRad, double cameraAltitudeM) {
        long start = System.nanoTime();
        float[] rgba = new float[WIDTH * HEIGHT * DEPTH * 4];
        IntStream.range(0, HEIGHT).parallel().forEach(y -> {
            SkyIntegrator integrator = new SkyIntegrator(t);
            double[] spectral = new double[t.spectrum().count()];
            Vector3d colour = new Vector3d();
            Vector3d transmittance = new Vector3d();
            double elevation = SkyView.elevation(y / (HEIGHT - 1.0));
            for (int x = 0; x < WIDTH; x++) {
                integrator.start(cameraAltitudeM, Math.PI * x / (WIDTH - 1.0), elevation, sunElevationRad);
                double length = integrator.length();
                double reached = 0;
                for (int z = 0; z < DEPTH; z++) {
                    double end = Math.min(sliceEnd(z), length);
                    if (end > reached) {
                        integrator.march(reached, end, STEPS_PER_SLICE);
                        reached = end;
                    }
                    double[] radiance = integrator.radiance();
                    for (int i = 0; i < spectral.length; i++) {
                        spectral[i] = Math.PI * radiance[i];
                    }
                    t.spectrum().toDisplayRgb(spectral, colour);
                    t.spectrum().toDisplayRgb(integrator.throughput(), transmittance);
                    int i = (((z * HEIGHT) + y) * WIDTH + x) * 4;
                    rgba[i] = (float) colour.x;
                    rgba[i + 1] = (float) colour.y;
                    rgba[i + 2] = (float) colour.z;
                    rgba[i + 3] = (float) ((transmittance.x + transmittance.y + transmittance.z) / 3);
                }
            }
        });
        return new AerialPerspective(rgba, (System.nanoTime() - start) / 1e6);
    }

    /** Distance at which slice k ends, m: MAX_DISTANCE·((k + 1)/DEPTH)². */
    public static double sliceEnd(int k) {
        double w = (k + 1.0) / DEPTH;
        return MAX_DISTANCE * w * w;
    }

    /** Texel values: in-scattered RGB and mean transmittance, {@code ((z·HEIGHT + y)·WIDTH + x)·4 + c}. */
    public float[] rgba() {
        return rgba;
    }

    /** Wall-clock time of {@link #build}, ms. */
    public double buildMillis() {
        return buildMillis;
    }

    /**
     * The volume at a direction and distance, interpolated as the shader does: bilinear over the direction, linear
     * in w = √(d / MAX_DISTANCE) between slices, and from (0, 0, 0, 1) at d = 0 to the first slice.
     */
    public Vector4d sample(double azimuthFromSunRad, double elevationRad, double distanceM, Vector4d out) {
        double[] uv = SkyView.uv(azimuthFromSunRad, elevationRad);
        double w = Math.sqrt(Math.max(distanceM, 0) / MAX_DISTANCE) * DEPTH - 1;
        if (w < 0) {
            Vector4d first = slice(uv[0], uv[1], 0, new Vector4d());
            double f = w + 1;
            return out.set(first.x * f, first.y * f, first.z * f, 1 + (first.w - 1) * f);
        }
        int z0 = Math.min((int) w, DEPTH - 2);
        double f = Math.min(w - z0, 1);
        Vector4d a = slice(uv[0], uv[1], z0, new Vector4d());
        Vector4d b = slice(uv[0], uv[1], z0 + 1, new Vector4d());
        return out.set(a).lerp(b, f);
    }

    /** Slice z bilinearly interpolated at unit coordinates (u, v). */
    private Vector4d slice(double u, double v, int z, Vector4d out) {
        double fx = TransmittanceTable.clamp(u, 0, 1) * (WIDTH - 1);
        double fy = TransmittanceTable.clamp(v, 0, 1) * (HEIGHT - 1);
        int x0 = Math.min((int) fx, WIDTH - 2);
        int y0 = Math.min((int) fy, HEIGHT - 2);
        double ax = fx - x0;
        double ay = fy - y0;
        double[] c = new double[4];
        for (int ch = 0; ch < 4; ch++) {
            double bottom = texel(x0, y0, z, ch) * (1 - ax) + texel(x0 + 1, y0, z, ch) * ax;
            double top = texel(x0, y0 + 1, z, ch) * (1 - ax) + texel(x0 + 1, y0 + 1, z, ch) * ax;
            c[ch] = bottom + (top - bottom) * ay;
        }
        return out.set(c[0], c[1], c[2], c[3]);
    }

    private double texel(int x, int y, int z, int channel) {
        return rgba[(((z * HEIGHT) + y) * WIDTH + x) * 4 + channel];
    }
}

package org.openworld.engine.sky;

import java.util.Arrays;
import java.util.stream.IntStream;

/**
 * Transmittance from any point of the atmosphere to its top, per wavelength: T(r, μ) = exp(−∫ σ_t ds) along the ray
 * that starts at radius r with zenith cosine μ. Hillaire 2020 section 4 / Bruneton 2017 section "Transmittance":
 * a {@value #WIDTH} × {@value #HEIGHT} table with Bruneton's parameterisation, which spends texels where T changes
 * fast (near the ground and near the horizon):
 * <pre>
 *   H = √(R_top² − R_ground²),  ρ = √(r² − R_ground²),  d = distance to the top along (r, μ)
 *   x_r = ρ / H,  x_μ = (d − d_min) / (d_max − d_min),  d_min = R_top − r,  d_max = ρ + H
 * </pre>
 * x_μ = 0 is the zenith and x_μ = 1 the horizon; rays below the horizon meet the ground and have T = 0 (the planet's
 * shadow). Each texel integrates σ_t with {@value #STEPS} midpoint steps. Texel i holds x = i / (N − 1), so
 * lookups interpolate bilinearly between texel centres as a GPU would.
 */
public final class TransmittanceTable {

    /** Texels along x_μ (Bruneton's and Hillaire's size). */
    public static final int WIDTH = 256;
    /** Texels along x_r. */
    public static final int HEIGHT = 64;
    /** Midpoint steps of the optical-depth integral per texel (Hillaire's 40: below 10⁻³ relative error). */
    private static final int STEPS = 40;

    private static final double H = Math.sqrt(Atmosphere.TOP_RADIUS * Atmosphere.TOP_RADIUS
            - Atmosphere.BOTTOM_RADIUS * Atmosphere.BOTTOM_RADIUS);

    private final int n;
    /** T per texel and wavelength: index (y·WIDTH + x)·n + i. */
    private final double[] values;

    private TransmittanceTable(int n, double[] values) {
        this.n = n;
        this.values = values;
    }

    /** Integrates every texel, rows in parallel. */
    static TransmittanceTable build(Atmosphere atmosphere) {
        int n = atmosphere.spectrum().count();
        double[] values = new double[WIDTH * HEIGHT * n];
        IntStream.range(0, HEIGHT).parallel().forEach(y -> {
            double[] extinction = new double[n];
            double[] depth = new double[n];
            double rho = H * y / (HEIGHT - 1.0);
            double r = Math.sqrt(rho * rho + Atmosphere.BOTTOM_RADIUS * Atmosphere.BOTTOM_RADIUS);
            for (int x = 0; x < WIDTH; x++) {
                double dMin = Atmosphere.TOP_RADIUS - r;
                double dMax = rho + H;
                double d = dMin + x / (WIDTH - 1.0) * (dMax - dMin);
                double mu = d == 0 ? 1 : clamp((H * H - rho * rho - d * d) / (2 * r * d), -1, 1);
                Arrays.fill(depth, 0);
                double dt = Spheres.distanceToTop(r, mu) / STEPS;
                for (int s = 0; s < STEPS; s++) {
                    double altitude = Spheres.radiusAt(r, mu, (s + 0.5) * dt) - Atmosphere.BOTTOM_RADIUS;
                    atmosphere.extinction(altitude, extinction);
                    for (int i = 0; i < n; i++) {
                        depth[i] += extinction[i] * dt;
                    }
                }
                int base = (y * WIDTH + x) * n;
                for (int i = 0; i < n; i++) {
                    values[base + i] = Math.exp(-depth[i]);
                }
            }
        });
        return new TransmittanceTable(n, values);
    }

    /**
     * Transmittance per wavelength from radius {@code radiusM} along zenith cosine {@code cosZenith} to the top of
     * the atmosphere, bilinear in the table; all 0 when the ray meets the ground. Returns {@code out}.
     */
    public double[] transmittance(double radiusM, double cosZenith, double[] out) {
        double r = clamp(radiusM, Atmosphere.BOTTOM_RADIUS, Atmosphere.TOP_RADIUS);
        if (Spheres.hitsGround(r, cosZenith)) {
            Arrays.fill(out, 0, n, 0);
            return out;
        }
        double rho = Math.sqrt(Math.max(r * r - Atmosphere.BOTTOM_RADIUS * Atmosphere.BOTTOM_RADIUS, 0));
        double d = Spheres.distanceToTop(r, cosZenith);
        double dMin = Atmosphere.TOP_RADIUS - r;
        double dMax = rho + H;
        double xMu = dMax > dMin ? clamp((d - dMin) / (dMax - dMin), 0, 1) : 0;
        double xR = clamp(rho / H, 0, 1);
        double fx = xMu * (WIDTH - 1);
        double fy = xR * (HEIGHT - 1);
        return bilinear(values, WIDTH, HEIGHT, n, fx, fy, out);
    }

    /**
     * Bilinear lookup in a table of {@code width × height} texels of {@code n} wavelengths each (row-major,
     * wavelengths innermost) at texel coordinates (fx, fy), each within 0 .. size − 1. Returns {@code out}.
     */
    static double[] bilinear(double[] values, int width, int height, int n, double fx, double fy, double[] out) {
        int x0 = Math.min((int) fx, width - 2);
        int y0 = Math.min((int) fy, height - 2);
        double ax = fx - x0;
        double ay = fy - y0;
        int b00 = (y0 * width + x0) * n;
        int b10 = b00 + n;
        int b01 = b00 + width * n;
        int b11 = b01 + n;
        for (int i = 0; i < n; i++) {
            double bottom = values[b00 + i] + (values[b10 + i] - values[b00 + i]) * ax;
            double top = values[b01 + i] + (values[b11 + i] - values[b01 + i]) * ax;
            out[i] = bottom + (top - bottom) * ay;
        }
        return out;
    }

    static double clamp(double v, double min, double max) {
        return Math.max(min, Math.min(max, v));
    }
}

package org.openworld.engine.sky;

import java.util.Arrays;
import java.util.stream.IntStream;

/**
 * Hillaire 2020 section 5.5: the light scattered two or more times, as an isotropic transfer Ψ_ms per wavelength in
 * a {@value #SIZE} × {@value #SIZE} table over the sun's zenith cosine μ_s ∈ [−1, 1] (x) and the altitude
 * h ∈ [0, 100 km] (y). At each texel, for {@value #DIRECTIONS} directions ω spread evenly over the sphere,
 * {@value #STEPS} steps march to the ground or the top and gather
 * <pre>
 *   L'(ω)    = ∫ T(x, x_t) σ_s(x_t) p_u T_sun(x_t) dt  +  T(x, x_ground)·T_sun(x_ground)·(n·s)·albedo/π
 *   f_ms(ω)  = ∫ T(x, x_t) σ_s(x_t) dt              (the transfer of unit isotropic light)
 * </pre>
 * with the isotropic phase p_u = 1/(4π). Their sphere averages are L_2nd and f_ms, and the geometric series of all
 * orders, each assumed to scatter like the second, gives Ψ_ms = L_2nd / (1 − f_ms) (Hillaire's equation 10), per unit
 * solar irradiance. The sky march then adds σ_s(x)·Ψ_ms(x) as in-scattered radiance at each sample. Integrals use
 * Hillaire's energy-conserving step ∫ T σ = T_0 · σ (1 − e^(−σ_t Δt)) / σ_t. Texel i holds x = i / (SIZE − 1).
 */
public final class MultipleScatteringTable {

    /** Texels per side (Hillaire's 32: Ψ_ms is smooth). */
    public static final int SIZE = 32;
    /** Directions per texel (Hillaire's 8 × 8). */
    private static final int DIRECTIONS_PER_SIDE = 8;
    private static final int DIRECTIONS = DIRECTIONS_PER_SIDE * DIRECTIONS_PER_SIDE;
    /** Steps per direction (Hillaire's 20). */
    private static final int STEPS = 20;
    /** Isotropic phase function, sr⁻¹. */
    private static final double ISOTROPIC_PHASE = 1 / (4 * Math.PI);

    private final int n;
    /** Ψ_ms per texel and wavelength, sr⁻¹ per unit solar irradiance: index (y·SIZE + x)·n + i. */
    private final double[] values;

    private MultipleScatteringTable(int n, double[] values) {
        this.n = n;
        this.values = values;
    }

    /** Integrates every texel, rows in parallel. */
    static MultipleScatteringTable build(Atmosphere atmosphere, TransmittanceTable transmittance) {
        int n = atmosphere.spectrum().count();
        double albedo = atmosphere.settings().groundAlbedo();
        double[] values = new double[SIZE * SIZE * n];
        double[][] directions = sphereDirections();
        IntStream.range(0, SIZE).parallel().forEach(y -> {
            double[] sunT = new double[n];
            double[] throughput = new double[n];
            double[] light = new double[n];
            double[] transfer = new double[n];
            double[] lightSum = new double[n];
            double[] transferSum = new double[n];
            double r = Atmosphere.BOTTOM_RADIUS + Math.max(y / (SIZE - 1.0) * Atmosphere.thickness(), 1);
            for (int x = 0; x < SIZE; x++) {
                double muS = -1 + 2 * x / (SIZE - 1.0);
                double sunX = Math.sqrt(Math.max(1 - muS * muS, 0));
                Arrays.fill(lightSum, 0);
                Arrays.fill(transferSum, 0);
                for (double[] w : directions) {
                    Arrays.fill(throughput, 1);
                    Arrays.fill(light, 0);
                    Arrays.fill(transfer, 0);
                    double mu = w[1];
                    boolean ground = Spheres.hitsGround(r, mu);
                    double length = Spheres.distanceToEdge(r, mu);
                    double dt = length / STEPS;
                    for (int s = 0; s < STEPS; s++) {
                        double t = (s + 0.5) * dt;
                        double px = t * w[0];
                        double py = r + t * w[1];
                        double pz = t * w[2];
                        double rp = Math.sqrt(px * px + py * py + pz * pz);
                        double altitude = rp - Atmosphere.BOTTOM_RADIUS;
                        transmittance.transmittance(rp, (px * sunX + py * muS) / rp, sunT);
                        double rayleigh = atmosphere.rayleighDensity(altitude);
                        double mie = atmosphere.mieDensity(altitude);
                        double ozone = Atmosphere.ozoneDensity(altitude);
                        for (int i = 0; i < n; i++) {
                            double scattering = atmosphere.rayleighScattering(i) * rayleigh
                                    + atmosphere.mieScattering() * mie;
                            double extinction = atmosphere.rayleighScattering(i) * rayleigh
                                    + atmosphere.mieExtinction() * mie + atmosphere.ozoneAbsorption(i) * ozone;
                            double stepT = Math.exp(-extinction * dt);
                            double integral = throughput[i] * scattering * (1 - stepT) / extinction;
                            light[i] += integral * ISOTROPIC_PHASE * sunT[i];
                            transfer[i] += integral;
                            throughput[i] *= stepT;
                        }
                    }
                    if (ground) {
                        double px = length * w[0];
                        double py = r + length * w[1];
                        double pz = length * w[2];
                        double rp = Math.sqrt(px * px + py * py + pz * pz);
                        double cosSun = (px * sunX + py * muS) / rp;
                        transmittance.transmittance(rp, cosSun, sunT);
                        double lambert = Math.max(cosSun, 0) * albedo / Math.PI;
                        for (int i = 0; i < n; i++) {
                            light[i] += throughput[i] * sunT[i] * lambert;
                        }
                    }
                    for (int i = 0; i < n; i++) {
                        lightSum[i] += light[i];
                        transferSum[i] += transfer[i];
                    }
                }
                int base = (y * SIZE + x) * n;
                for (int i = 0; i < n; i++) {
                    // Sphere average: Σ · (4π / DIRECTIONS) · p_u = Σ / DIRECTIONS.
                    double secondOrder = lightSum[i] / DIRECTIONS;
                    double fms = transferSum[i] / DIRECTIONS;
                    values[base + i] = secondOrder / (1 - fms);
                }
            }
        });
        return new MultipleScatteringTable(n, values);
    }

    /** Ψ_ms per wavelength at a radius and sun zenith cosine, bilinear in the table. Returns {@code out}. */
    public double[] psi(double radiusM, double sunCosZenith, double[] out) {
        double fx = TransmittanceTable.clamp((sunCosZenith + 1) / 2, 0, 1) * (SIZE - 1);
        double fy = TransmittanceTable.clamp((radiusM - Atmosphere.BOTTOM_RADIUS) / Atmosphere.thickness(), 0, 1)
                * (SIZE - 1);
        return TransmittanceTable.bilinear(values, SIZE, SIZE, n, fx, fy, out);
    }

    /** Hillaire's even sphere sampling: θ = 2π·a, φ = acos(1 − 2b) on an 8 × 8 grid of cell centres (a, b). */
    private static double[][] sphereDirections() {
        double[][] directions = new double[DIRECTIONS][];
        for (int j = 0; j < DIRECTIONS_PER_SIDE; j++) {
            for (int i = 0; i < DIRECTIONS_PER_SIDE; i++) {
                double theta = 2 * Math.PI * (i + 0.5) / DIRECTIONS_PER_SIDE;
                double cosPhi = 1 - 2 * (j + 0.5) / DIRECTIONS_PER_SIDE;
                double sinPhi = Math.sqrt(1 - cosPhi * cosPhi);
                directions[j * DIRECTIONS_PER_SIDE + i] =
                        new double[] {Math.cos(theta) * sinPhi, cosPhi, Math.sin(theta) * sinPhi};
            }
        }
        return directions;
    }
}

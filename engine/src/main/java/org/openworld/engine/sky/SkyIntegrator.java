package org.openworld.engine.sky;

import java.util.Arrays;

/**
 * The one implementation of "light scattered toward the eye along a view ray", used by {@link SkyView},
 * {@link AerialPerspective} and {@link SkyReference}. It works in the eye's local frame: the eye at (0, r, 0) above
 * the planet's centre, Y up, the sun in the XY plane at elevation e_s, and a view direction at elevation e and
 * azimuth φ from the sun's vertical plane:
 * <pre>
 *   sun  s = (cos e_s, sin e_s, 0)        view  v = (cos e·cos φ, sin e, cos e·sin φ)
 * </pre>
 * A ray is marched in segments ({@link #march}) so a caller can read the accumulated radiance L and the
 * transmittance T from the eye after each one. Radiance is per unit solar irradiance (E_sun = 1), sr⁻¹; callers
 * report π·L (display units). The mode follows {@link AtmosphereSettings#scattering()}:
 * <ul>
 * <li>{@code MULTIPLE} (Hillaire 2020 section 5): at each sample x_t,
 *     S = T_sun(x_t)·(σ_s,R p_R(θ) + σ_s,M p_M(θ)) + Ψ_ms(x_t)·(σ_s,R + σ_s,M), integrated with the energy-conserving
 *     step L += T·S·(1 − e^(−σ_t Δt))/σ_t. T_sun comes from the {@link TransmittanceTable} (0 in the planet's
 *     shadow).</li>
 * <li>{@code SINGLE} (the paper's equations 3 and 4 literally): L += e^(−t(a,p))·e^(−t(p,c))·(σ_s,R p_R + σ_s,M p_M)·Δs
 *     at the midpoints p of the outer sum, where t(p, c) is the inner sum of σ_t over
 *     {@link AtmosphereSettings#innerSamples()} points from p toward the sun to the top of the atmosphere, and
 *     t(a, p) accumulates along the outer sum. Points whose sun ray meets the planet get no light.</li>
 * </ul>
 * The {@link AtmosphereSettings#component()} keeps only Rayleigh's or only Mie's σ_s in S (figure 8); σ_t always
 * counts every particle. Not thread-safe: one integrator per thread (it holds scratch arrays).
 */
final class SkyIntegrator {

    /** Lowest eye altitude, m: keeps the eye above the ground so rays just below the horizon still meet it. */
    private static final double MIN_ALTITUDE = 1;
    /** Most steps of a MULTIPLE dome ray (Hillaire's sky-view LUT: up to 30), taken by rays of ≥ 100 km. */
    static final int DOME_STEPS = 30;
    /** Fewest steps of a MULTIPLE dome ray, for rays that meet the ground close by (Hillaire's minimum, 4). */
    private static final int DOME_MIN_STEPS = 4;
    /** Ray length that gets {@link #DOME_STEPS} steps, m: the zenith ray through the whole atmosphere. */
    private static final double DOME_FULL_LENGTH = 100_000;

    private final Atmosphere atmosphere;
    private final TransmittanceTable transmittanceTable;
    private final MultipleScatteringTable multipleTable;
    private final boolean single;
    private final int innerSamples;
    private final int outerSamples;
    private final double rayleighOn;
    private final double mieOn;
    private final double g;
    private final int n;

    private final double[] radiance;
    private final double[] throughput;
    private final double[] sunTransmittance;
    private final double[] psi;
    /** SINGLE mode: ∫ρ_R ds, ∫ρ_M ds, ∫ρ_O ds along the view ray so far, m. */
    private double viewRayleigh;
    private double viewMie;
    private double viewOzone;

    private double radius;
    private double vx;
    private double vy;
    private double vz;
    private double sx;
    private double sy;
    private double rayleighPhase;
    private double miePhase;

    SkyIntegrator(AtmosphereTables tables) {
        atmosphere = tables.atmosphere();
        transmittanceTable = tables.transmittance();
        multipleTable = tables.multipleScattering();
        AtmosphereSettings s = tables.settings();
        single = s.scattering() == AtmosphereSettings.Scattering.SINGLE;
        innerSamples = s.innerSamples();
        outerSamples = s.outerSamples();
        rayleighOn = s.component().rayleigh() ? 1 : 0;
        mieOn = s.component().mie() ? 1 : 0;
        g = s.mieAnisotropy();
        n = tables.spectrum().count();
        radiance = new double[n];
        throughput = new double[n];
        sunTransmittance = new double[n];
        psi = new double[n];
    }

    /** Radius of the eye for a camera altitude, m: clamped inside the atmosphere. */
    static double eyeRadius(double cameraAltitudeM) {
        return Atmosphere.BOTTOM_RADIUS
                + TransmittanceTable.clamp(cameraAltitudeM, MIN_ALTITUDE, Atmosphere.thickness() - MIN_ALTITUDE);
    }

    /**
     * Starts a ray: radiance 0, transmittance 1. Angles in radians; the azimuth is measured from the sun's
     * vertical plane.
     */
    void start(double cameraAltitudeM, double azimuthFromSun, double elevation, double sunElevation) {
        radius = eyeRadius(cameraAltitudeM);
        double cosE = Math.cos(elevation);
        vx = cosE * Math.cos(azimuthFromSun);
        vy = Math.sin(elevation);
        vz = cosE * Math.sin(azimuthFromSun);
        sx = Math.cos(sunElevation);
        sy = Math.sin(sunElevation);
        double cosTheta = vx * sx + vy * sy;
        rayleighPhase = Atmosphere.rayleighPhase(cosTheta);
        miePhase = Atmosphere.miePhase(cosTheta, g);
        Arrays.fill(radiance, 0);
        Arrays.fill(throughput, 1);
        viewRayleigh = 0;
        viewMie = 0;
        viewOzone = 0;
    }

    /** Distance from the eye to the ground or the top of the atmosphere along the ray, m. */
    double length() {
        return Spheres.distanceToEdge(radius, vy);
    }

    /** Marches [from, to] metres along the ray in {@code steps} equal steps, accumulating L and T. */
    void march(double from, double to, int steps) {
        double dt = (to - from) / steps;
        if (!(dt > 0)) {
            return;
        }
        for (int s = 0; s < steps; s++) {
            double t = from + (s + 0.5) * dt;
            double px = t * vx;
            double py = radius + t * vy;
            double pz = t * vz;
            double rp = Math.sqrt(px * px + py * py + pz * pz);
            double sunCos = (px * sx + py * sy) / rp;
            double altitude = rp - Atmosphere.BOTTOM_RADIUS;
            double rayleighDensity = atmosphere.rayleighDensity(altitude);
            double mieDensity = atmosphere.mieDensity(altitude);
            double ozoneDensity = Atmosphere.ozoneDensity(altitude);
            if (single) {
                singleStep(rp, sunCos, rayleighDensity, mieDensity, ozoneDensity, dt);
            } else {
                multipleStep(rp, sunCos, rayleighDensity, mieDensity, ozoneDensity, dt);
            }
        }
        if (single) {
            for (int i = 0; i < n; i++) {
                throughput[i] = Math.exp(-(atmosphere.rayleighScattering(i) * viewRayleigh
                        + atmosphere.mieExtinction() * viewMie + atmosphere.ozoneAbsorption(i) * viewOzone));
            }
        }
    }

    /** Hillaire's step: table transmittance toward the sun, Ψ_ms, energy-conserving integration. */
    private void multipleStep(double rp, double sunCos, double rayleighDensity, double mieDensity,
                              double ozoneDensity, double dt) {
        transmittanceTable.transmittance(rp, sunCos, sunTransmittance);
        multipleTable.psi(rp, sunCos, psi);
        double mieScattering = atmosphere.mieScattering() * mieDensity * mieOn;
        for (int i = 0; i < n; i++) {
            double rayleighScattering = atmosphere.rayleighScattering(i) * rayleighDensity * rayleighOn;
            double sigmaT = atmosphere.rayleighScattering(i) * rayleighDensity
                    + atmosphere.mieExtinction() * mieDensity + atmosphere.ozoneAbsorption(i) * ozoneDensity;
            double source = sunTransmittance[i] * (rayleighScattering * rayleighPhase + mieScattering * miePhase)
                    + psi[i] * (rayleighScattering + mieScattering);
            double stepT = Math.exp(-sigmaT * dt);
            radiance[i] += throughput[i] * source * (1 - stepT) / sigmaT;
            throughput[i] *= stepT;
        }
    }

    /**
     * The paper's step: e^(−t(a,p))·e^(−t(p,c))·K·F·Δs at the step's midpoint p. As in equation 3, an optical depth
     * is K(λ) times a density integral, so the sums gather ∫ρ ds per particle kind once for all wavelengths.
     */
    private void singleStep(double rp, double sunCos, double rayleighDensity, double mieDensity,
                            double ozoneDensity, double dt) {
        // t(a, p): the view ray's density integrals up to the midpoint.
        viewRayleigh += rayleighDensity * dt * 0.5;
        viewMie += mieDensity * dt * 0.5;
        viewOzone += ozoneDensity * dt * 0.5;
        if (!Spheres.hitsGround(rp, sunCos)) {
            // t(p, c): the inner sum toward the sun, to the top of the atmosphere.
            double sunRayleigh = 0;
            double sunMie = 0;
            double sunOzone = 0;
            double ds = Spheres.distanceToTop(rp, sunCos) / innerSamples;
            for (int k = 0; k < innerSamples; k++) {
                double h = Spheres.radiusAt(rp, sunCos, (k + 0.5) * ds) - Atmosphere.BOTTOM_RADIUS;
                sunRayleigh += atmosphere.rayleighDensity(h) * ds;
                sunMie += atmosphere.mieDensity(h) * ds;
                sunOzone += Atmosphere.ozoneDensity(h) * ds;
            }
            double rayleighDepth = viewRayleigh + sunRayleigh;
            double mieDepth = (viewMie + sunMie) * atmosphere.mieExtinction();
            double ozoneDepth = viewOzone + sunOzone;
            double mieScattering = atmosphere.mieScattering() * mieDensity * mieOn * miePhase;
            for (int i = 0; i < n; i++) {
                double beta = atmosphere.rayleighScattering(i);
                double depth = beta * rayleighDepth + mieDepth + atmosphere.ozoneAbsorption(i) * ozoneDepth;
                double scattered = beta * rayleighDensity * rayleighOn * rayleighPhase + mieScattering;
                radiance[i] += Math.exp(-depth) * scattered * dt;
            }
        }
        viewRayleigh += rayleighDensity * dt * 0.5;
        viewMie += mieDensity * dt * 0.5;
        viewOzone += ozoneDensity * dt * 0.5;
    }

    /** Accumulated in-scattered radiance per wavelength, sr⁻¹ per unit solar irradiance (live array). */
    double[] radiance() {
        return radiance;
    }

    /** Transmittance from the eye to the end of the last segment, per wavelength (live array). */
    double[] throughput() {
        return throughput;
    }

    /**
     * π·L of one dome direction per wavelength into {@code out}: the ray marched to the ground or the top in
     * {@link AtmosphereSettings#outerSamples()} steps (SINGLE), or (MULTIPLE) in {@value #DOME_STEPS} steps scaled
     * down with the ray's length below 100 km, at least {@value #DOME_MIN_STEPS} (Hillaire's variable sample count:
     * rays that soon meet the ground cross little air and need few steps). This is the code
     * {@link SkyView} runs per texel and {@link SkyReference} per call.
     */
    double[] dome(double cameraAltitudeM, double azimuthFromSun, double elevation, double sunElevation,
                  double[] out) {
        start(cameraAltitudeM, azimuthFromSun, elevation, sunElevation);
        double length = length();
        int steps = single ? outerSamples : (int) Math.max(DOME_MIN_STEPS,
                Math.min(DOME_STEPS, Math.ceil(DOME_STEPS * length / DOME_FULL_LENGTH)));
        march(0, length, steps);
        for (int i = 0; i < n; i++) {
            out[i] = Math.PI * radiance[i];
        }
        return out;
    }
}

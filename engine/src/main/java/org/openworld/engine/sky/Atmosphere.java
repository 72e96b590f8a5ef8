package org.openworld.engine.sky;

/**
 * The atmosphere for one {@link Spectrum} and {@link AtmosphereSettings}: the particles, their density profiles and
 * their phase functions, in SI units. {@link AtmosphereSettings#constants()} picks one of two sets of constants.
 * <p>{@code PHYSICAL}: Earth's, Bruneton 2017's ("Precomputed Atmospheric Scattering: a New Implementation", its
 * demo's constants), which Hillaire 2020 uses too.
 * <ul>
 * <li>Rayleigh (molecules): scattering β_R(λ) = 1.24062·10⁻⁶·(λ / 1 µm)⁻⁴ m⁻¹ at sea level, no absorption,
 *     density e^(−h / 8 km), phase p_R(θ) = 3/(16π)·(1 + cos²θ).</li>
 * <li>Mie (aerosols): scattering 3.996·10⁻⁶ m⁻¹, extinction 4.44·10⁻⁶ m⁻¹ (single-scattering albedo 0.9) at sea
 *     level, both times {@code haze}, grey, density e^(−h / 1.2 km), Cornette–Shanks phase
 *     p_M(θ) = 3/(8π)·(1 − g²)(1 + cos²θ) / ((2 + g²)(1 + g² − 2g·cosθ)^{3/2}).</li>
 * <li>Ozone: absorption only, σ_O(λ) = n_max·C(λ) with the cross-section C(λ) of the Bremen 2011 spectra at 233 K,
 *     a tent profile (0 at 10 km, 1 at 25 km, 0 at 40 km, integral 15 km) and n_max chosen for 300 Dobson units
 *     (times {@code ozone}). Ozone absorbs around 600 nm: it is why the twilight zenith stays blue.</li>
 * </ul>
 * <p>{@code NORMALISED}: the paper's (3.1, after O'Neil 2005, GPU Gems 2 chapter 16). Heights count in units of the
 * shell's thickness H0 = {@value #TOP_RADIUS} − {@value #BOTTOM_RADIUS} m, so x = h/H0 runs from 0 to 1, and so do
 * the lengths of the optical depths: t = 4π·K·λ⁻⁴·∫ρ d(s/H0), λ in µm. As coefficients per metre that is
 * β_R(λ) = 4π·{@value #NORMALISED_K_R}·(λ / 1 µm)⁻⁴ / H0 and β_M = 4π·{@value #NORMALISED_K_M}·{@code haze} / H0
 * (grey, scattering only), with densities e^(−x / 0.25) and e^(−x / 0.1) (O'Neil's scale depths: 25 km and 10 km
 * here), the same phase functions, and no ozone. The sun is the same E_sun = 1 as in {@code PHYSICAL}: the exposure
 * that O'Neil tuned by hand together with his sun intensity is the scene's automatic one.
 * <p>The planet is a sphere of radius {@value #BOTTOM_RADIUS} m; the atmosphere ends at {@value #TOP_RADIUS} m.
 */
public final class Atmosphere {

    /** Ground radius, m (Bruneton's and Hillaire's Earth). */
    public static final double BOTTOM_RADIUS = 6_360_000;
    /** Radius of the top of the atmosphere, m: 100 km up, where the Rayleigh density is e^(−12.5) ≈ 4·10⁻⁶. */
    public static final double TOP_RADIUS = 6_460_000;

    /** Rayleigh scattering at 1 µm and sea level, m⁻¹ (Bruneton 2017, kRayleigh). */
    private static final double RAYLEIGH_AT_1_MICRON = 1.24062e-6;
    /** Rayleigh scale height, m. */
    private static final double RAYLEIGH_SCALE_HEIGHT = 8000;
    /** Mie scattering at sea level, m⁻¹ (Bruneton: 5.328·10⁻³ / 1200 m × albedo 0.9). */
    private static final double MIE_SCATTERING = 3.996e-6;
    /** Mie extinction at sea level, m⁻¹ (5.328·10⁻³ / 1200 m). */
    private static final double MIE_EXTINCTION = 4.44e-6;
    /** Mie scale height, m. */
    private static final double MIE_SCALE_HEIGHT = 1200;
    /** NORMALISED: O'Neil's Rayleigh constant K_R (per unit of normalised length, times λ⁴ in µm⁴). */
    static final double NORMALISED_K_R = 0.0025;
    /** NORMALISED: O'Neil's Mie constant K_M (per unit of normalised length). */
    static final double NORMALISED_K_M = 0.0010;
    /** NORMALISED: O'Neil's Rayleigh scale depth, a fraction of H0. */
    private static final double NORMALISED_RAYLEIGH_DEPTH = 0.25;
    /** NORMALISED: O'Neil's Mie scale depth, a fraction of H0. */
    private static final double NORMALISED_MIE_DEPTH = 0.1;
    /** Ozone tent: altitude of the density peak, m. */
    private static final double OZONE_PEAK = 25_000;
    /** Ozone tent: half width, m (0 at 10 km and at 40 km). */
    private static final double OZONE_HALF_WIDTH = 15_000;
    /** One Dobson unit, molecules per m² (2.687·10²⁰). */
    private static final double DOBSON_UNIT = 2.687e20;
    /** Column of the standard ozone layer, Dobson units (the global mean). */
    private static final double OZONE_COLUMN_DU = 300;
    /** First wavelength of {@link #OZONE_CROSS_SECTION}, nm. */
    private static final double OZONE_FIRST_NM = 360;
    /** Step of {@link #OZONE_CROSS_SECTION}, nm. */
    private static final double OZONE_STEP_NM = 10;
    /**
     * Ozone absorption cross-section, m², at 360, 370, ... 830 nm: Bruneton 2017's kOzoneCrossSection (Bremen
     * o3spectra2011 at 233 K, averaged over each 10 nm bin).
     */
    private static final double[] OZONE_CROSS_SECTION = {
            1.18e-27, 2.182e-28, 2.818e-28, 6.636e-28, 1.527e-27, 2.763e-27, 5.52e-27,
            8.451e-27, 1.582e-26, 2.316e-26, 3.669e-26, 4.924e-26, 7.752e-26, 9.016e-26,
            1.48e-25, 1.602e-25, 2.139e-25, 2.755e-25, 3.091e-25, 3.5e-25, 4.266e-25,
            4.672e-25, 4.398e-25, 4.701e-25, 5.019e-25, 4.305e-25, 3.74e-25, 3.215e-25,
            2.662e-25, 2.238e-25, 1.852e-25, 1.473e-25, 1.209e-25, 9.423e-26, 7.455e-26,
            6.566e-26, 5.105e-26, 4.15e-26, 4.228e-26, 3.237e-26, 2.451e-26, 2.801e-26,
            2.534e-26, 1.624e-26, 1.465e-26, 2.078e-26, 1.383e-26, 7.105e-27};

    private final AtmosphereSettings settings;
    private final Spectrum spectrum;
    private final double[] rayleighScattering;
    private final double[] ozoneAbsorption;
    private final double mieScattering;
    private final double mieExtinction;
    private final double rayleighScaleHeight;
    private final double mieScaleHeight;

    public Atmosphere(Spectrum spectrum, AtmosphereSettings settings) {
        this.settings = settings;
        this.spectrum = spectrum;
        int n = spectrum.count();
        rayleighScattering = new double[n];
        ozoneAbsorption = new double[n];
        if (settings.constants() == AtmosphereSettings.Constants.NORMALISED) {
            double perMetre = 4 * Math.PI / thickness();
            for (int i = 0; i < n; i++) {
                rayleighScattering[i] = perMetre * NORMALISED_K_R / Math.pow(spectrum.wavelengthNm(i) * 1e-3, 4);
            }
            mieScattering = perMetre * NORMALISED_K_M * settings.haze();
            mieExtinction = mieScattering;
            rayleighScaleHeight = NORMALISED_RAYLEIGH_DEPTH * thickness();
            mieScaleHeight = NORMALISED_MIE_DEPTH * thickness();
            return;
        }
        // The tent integrates to one half width (15 km): n_max · 15 km = 300 DU.
        double ozonePeakDensity = settings.ozone() * OZONE_COLUMN_DU * DOBSON_UNIT / OZONE_HALF_WIDTH;
        for (int i = 0; i < n; i++) {
            double microns = spectrum.wavelengthNm(i) * 1e-3;
            rayleighScattering[i] = RAYLEIGH_AT_1_MICRON / Math.pow(microns, 4);
            ozoneAbsorption[i] = ozonePeakDensity * ozoneCrossSection(spectrum.wavelengthNm(i));
        }
        mieScattering = MIE_SCATTERING * settings.haze();
        mieExtinction = MIE_EXTINCTION * settings.haze();
        rayleighScaleHeight = RAYLEIGH_SCALE_HEIGHT;
        mieScaleHeight = MIE_SCALE_HEIGHT;
    }

    public AtmosphereSettings settings() {
        return settings;
    }

    public Spectrum spectrum() {
        return spectrum;
    }

    /** Height of the atmosphere, m. */
    public static double thickness() {
        return TOP_RADIUS - BOTTOM_RADIUS;
    }

    /** Rayleigh scattering at sea level for wavelength i, m⁻¹. */
    public double rayleighScattering(int i) {
        return rayleighScattering[i];
    }

    /** Mie scattering at sea level (grey), m⁻¹. */
    public double mieScattering() {
        return mieScattering;
    }

    /** Mie extinction at sea level (grey), m⁻¹. */
    public double mieExtinction() {
        return mieExtinction;
    }

    /** Ozone absorption at the layer's peak density for wavelength i, m⁻¹. */
    public double ozoneAbsorption(int i) {
        return ozoneAbsorption[i];
    }

    /** Relative Rayleigh density at an altitude: e^(−h / 8 km), or NORMALISED e^(−(h/H0) / 0.25). */
    public double rayleighDensity(double altitudeM) {
        return Math.exp(-altitudeM / rayleighScaleHeight);
    }

    /** Relative Mie density at an altitude: e^(−h / 1.2 km), or NORMALISED e^(−(h/H0) / 0.1). */
    public double mieDensity(double altitudeM) {
        return Math.exp(-altitudeM / mieScaleHeight);
    }

    /** Relative ozone density at an altitude: the tent max(0, 1 − |h − 25 km| / 15 km). */
    public static double ozoneDensity(double altitudeM) {
        return Math.max(0, 1 - Math.abs(altitudeM - OZONE_PEAK) / OZONE_HALF_WIDTH);
    }

    /** Extinction σ_t(h, λ_i) = β_R·ρ_R + β_M,ext·ρ_M + σ_O·ρ_O for every wavelength, m⁻¹, into {@code out}. */
    public double[] extinction(double altitudeM, double[] out) {
        double r = rayleighDensity(altitudeM);
        double m = mieDensity(altitudeM) * mieExtinction;
        double o = ozoneDensity(altitudeM);
        for (int i = 0; i < out.length; i++) {
            out[i] = rayleighScattering[i] * r + m + ozoneAbsorption[i] * o;
        }
        return out;
    }

    /** Rayleigh phase function 3/(16π)·(1 + cos²θ), sr⁻¹. */
    public static double rayleighPhase(double cosTheta) {
        return 3 / (16 * Math.PI) * (1 + cosTheta * cosTheta);
    }

    /** Cornette–Shanks phase function with anisotropy g, sr⁻¹ (integrates to 1 over the sphere). */
    public static double miePhase(double cosTheta, double g) {
        double g2 = g * g;
        double denominator = Math.max(1 + g2 - 2 * g * cosTheta, 1e-12);
        return 3 / (8 * Math.PI) * (1 - g2) * (1 + cosTheta * cosTheta)
                / ((2 + g2) * denominator * Math.sqrt(denominator));
    }

    /** Cross-section C(λ) of ozone, m², linearly interpolated in the 10 nm table. */
    static double ozoneCrossSection(double nm) {
        double position = Math.max(0, Math.min((nm - OZONE_FIRST_NM) / OZONE_STEP_NM,
                OZONE_CROSS_SECTION.length - 1));
        int i = Math.min((int) position, OZONE_CROSS_SECTION.length - 2);
        double f = position - i;
        return OZONE_CROSS_SECTION[i] * (1 - f) + OZONE_CROSS_SECTION[i + 1] * f;
    }
}

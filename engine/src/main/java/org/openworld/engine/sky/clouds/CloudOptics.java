package org.openworld.engine.sky.clouds;

/**
 * The two curves the cloud shader looks up rather than computes (GL-free, so they are tested against their
 * formulas): the height profile that makes a cloud stratus or cumulus, and the phase function that sends sunlight
 * forward through a cloud's rim (the silver lining) and a little back towards the sun. {@link #table} writes both
 * into the 256 × 1 texture {@code cloudOptics} of {@code shaders/clouds/volume.glsl}.
 *
 * <h2>Height profile</h2>
 * Of the layer's height h (0 at the base, 1 at the top), how far up a cloud of full cover reaches: the density
 * shader keeps {@code cover + profile − 1}, so where the profile is 1 any cover is cloud and where it is 0 none.
 * Stratus (type 0) is a sheet in the lowest fifth; cumulus (type 1) has a flat base and falls linearly to the top,
 * so a cloud rises as high as its cover is strong (cover − h): the cover's smooth hills become rounded towers, the
 * strongest reaching the top. Types between blend the two linearly:
 * <pre>
 *   stratus(h) = S(0, 0.05, h) · (1 − S(0.1, 0.25, h))      cumulus(h) = S(0, 0.08, h) · (1 − h)
 *   profile(h) = (1 − type) · stratus(h) + type · cumulus(h)          S = smoothstep
 * </pre>
 *
 * <h2>Phase</h2>
 * The dual-lobe Henyey–Greenstein phase of cloud droplets (Hillaire 2016, "Physically based sky, atmosphere and
 * cloud rendering in Frostbite"), per steradian, normalised over the sphere:
 * <pre>
 *   HG(μ, g) = (1 − g²) / (4π (1 + g² − 2gμ)^1.5)      p(μ) = w HG(μ, g₁) + (1 − w) HG(μ, g₂)
 * </pre>
 * with μ the cosine of the angle between the view ray and the sun, g₁ = {@value #FORWARD} forward (the lining),
 * g₂ = {@value #BACKWARD} backward, w = {@value #FORWARD_SHARE}; its mean cosine is w g₁ + (1 − w) g₂. The
 * multiple-scattering octaves (Wrenninge et al. 2013) see the anisotropy times {@value #OCTAVE_C}^i: octave 1 and 2
 * are the table's b and a channels.
 */
public final class CloudOptics {

    /** Texels of the table: over h for the profile, over μ from −1 to 1 for the phase (0.008 in μ each). */
    public static final int SIZE = 256;
    /** Forward lobe's anisotropy: cloud droplets scatter most light within 10–20° of straight on. */
    static final double FORWARD = 0.8;
    /** Backward lobe's anisotropy: the glory side, weak. */
    static final double BACKWARD = -0.3;
    /** Share of the forward lobe. */
    static final double FORWARD_SHARE = 0.75;
    /** Each octave of multiple scattering sees the anisotropy times this (the octave papers' 0.5). */
    static final double OCTAVE_C = 0.5;

    private CloudOptics() {
    }

    /** The height profile at the height fraction h (clamped to 0..1) for a type from 0 (stratus) to 1 (cumulus). */
    public static double heightProfile(double h, double type) {
        double x = Math.min(Math.max(h, 0), 1);
        double stratus = smoothstep(0, 0.05, x) * (1 - smoothstep(0.1, 0.25, x));
        double cumulus = smoothstep(0, 0.08, x) * (1 - x);
        return (1 - type) * stratus + type * cumulus;
    }

    /** Henyey–Greenstein's phase per steradian at the cosine μ for the anisotropy g. */
    public static double henyeyGreenstein(double mu, double g) {
        double d = 1 + g * g - 2 * g * mu;
        return (1 - g * g) / (4 * Math.PI * d * Math.sqrt(d));
    }

    /** The clouds' dual-lobe phase per steradian at μ, its anisotropies scaled by {@code scale} (an octave's). */
    public static double phase(double mu, double scale) {
        return FORWARD_SHARE * henyeyGreenstein(mu, FORWARD * scale)
                + (1 - FORWARD_SHARE) * henyeyGreenstein(mu, BACKWARD * scale);
    }

    /**
     * The texture's texels, RGBA per texel: r the height profile at h = (i + 0.5) / SIZE, g, b, a the phase of octaves
     * 0, 1, 2 at μ = 2 (i + 0.5) / SIZE − 1 (the shader reads texel centres with linear filtering).
     */
    public static float[] table(double type) {
        float[] t = new float[4 * SIZE];
        for (int i = 0; i < SIZE; i++) {
            double x = (i + 0.5) / SIZE;
            double mu = 2 * x - 1;
            t[4 * i] = (float) heightProfile(x, type);
            t[4 * i + 1] = (float) phase(mu, 1);
            t[4 * i + 2] = (float) phase(mu, OCTAVE_C);
            t[4 * i + 3] = (float) phase(mu, OCTAVE_C * OCTAVE_C);
        }
        return t;
    }

    private static double smoothstep(double edge0, double edge1, double x) {
        double t = Math.min(Math.max((x - edge0) / (edge1 - edge0), 0), 1);
        return t * t * (3 - 2 * t);
    }
}

package org.openworld.engine.sky;

/**
 * Everything about the sky that does not depend on the sun's position: the sampled spectrum, the atmosphere and
 * its two precomputed tables (Hillaire 2020's transmittance and multiple-scattering LUTs). Rebuilt only when the
 * {@link AtmosphereSettings} change; the per-sun tables ({@link SkyView}, {@link AerialPerspective}) read it.
 *
 * @param settings          the settings it was built for
 * @param spectrum          the wavelengths and their conversion to RGB
 * @param atmosphere        particles and profiles at those wavelengths
 * @param transmittance     T(r, μ) to the top of the atmosphere
 * @param multipleScattering Ψ_ms(r, μ_s)
 * @param buildMillis       wall-clock time the build took, ms
 */
public record AtmosphereTables(AtmosphereSettings settings, Spectrum spectrum, Atmosphere atmosphere,
                               TransmittanceTable transmittance, MultipleScatteringTable multipleScattering,
                               double buildMillis) {

    /** Builds the spectrum, the atmosphere and both tables (in parallel over table rows). */
    public static AtmosphereTables build(AtmosphereSettings s) {
        long start = System.nanoTime();
        Spectrum spectrum = Spectrum.sampled(s.wavelengths());
        Atmosphere atmosphere = new Atmosphere(spectrum, s);
        TransmittanceTable transmittance = TransmittanceTable.build(atmosphere);
        MultipleScatteringTable multiple = MultipleScatteringTable.build(atmosphere, transmittance);
        return new AtmosphereTables(s, spectrum, atmosphere, transmittance, multiple,
                (System.nanoTime() - start) / 1e6);
    }
}

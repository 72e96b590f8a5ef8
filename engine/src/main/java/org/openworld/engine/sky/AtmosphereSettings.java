package org.openworld.engine.sky;

import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Settings of the physical sky (paper 3.1), keys {@code atmosphere.*}: which scattering model fills the sky tables,
 * how finely the spectrum and the paper's sums are sampled, and what the air holds.
 *
 * @param scattering    {@code MULTIPLE}: Hillaire 2020's tables (transmittance + multiple-scattering transfer Ψ_ms,
 *                      one ray march per sky texel), which keep twilight bright; {@code SINGLE}: the paper's
 *                      first-order equations 3–4 evaluated literally by nested sums, dark at dawn and dusk as in
 *                      the paper's figure 9 a and f
 * @param constants     the air's constants: {@code PHYSICAL} (Earth's, in metres: Bruneton 2017) or {@code NORMALISED}
 *                      (the paper's: height normalised by the shell's thickness H0, O'Neil 2005's scale depths and
 *                      K_R, K_M, no ozone; see {@link Atmosphere}). Either scattering model runs on either set
 * @param component     which particles scatter light toward the eye (figure 8): {@code BOTH}, {@code RAYLEIGH}
 *                      (molecules, the blue background) or {@code MIE} (aerosols, the glow around the sun).
 *                      Extinction always counts every particle, so only the in-scattering changes
 * @param wavelengths   spectral samples spread over 400–750 nm by the midpoint rule; the paper found at least 6
 *                      are needed for the colours to settle, because scattering does not blend additively in RGB.
 *                      Up to 32, the reference {@link SkyPicture}'s findings are measured against
 * @param outerSamples  SINGLE mode: points of the outer sum along the view ray (equation 4); the paper found 2
 *                      enough, with physical constants 16 are needed, with normalised ones 4 (docs/sky.md); 1
 *                      shows why
 * @param innerSamples  SINGLE mode: points of the inner sum toward the sun (equation 3's optical depth); as outer
 * @param haze          multiplier of the aerosol (Mie) density: 0 clean air, 1 a clear day, 10+ a hazy one
 * @param ozone         multiplier of the 300 Dobson-unit ozone layer; ozone absorbs orange light and keeps the
 *                      twilight zenith blue
 * @param mieAnisotropy g of the Cornette–Shanks phase function: 0 scatters evenly, 0.99 almost only forward
 * @param groundAlbedo  reflectance of the ground, which lights the air from below in the multiple-scattering term
 * @param fog           what the air between the eye and a surface does ({@link AerialPerspective}): {@code AERIAL}
 *                      the scattering along the ray, {@code SIMPLE} the paper's distance fog, exp(−d/D) towards the
 *                      sky's horizon colour
 * @param fogDistance   SIMPLE fog: the distance D over which the fog lets through 1/e of a surface's light, m
 */
public record AtmosphereSettings(
        @Setting(doc = "scattering model: MULTIPLE (Hillaire 2020) or SINGLE (the paper's eq. 3-4)")
        Scattering scattering,
        @Setting(doc = "the air's constants: PHYSICAL (Earth's, metres) or NORMALISED (the paper's h/H0, O'Neil)")
        Constants constants,
        @Setting(doc = "particles that scatter light to the eye: BOTH, RAYLEIGH or MIE (figure 8)")
        Component component,
        @Setting(doc = "spectral samples over 400-750 nm (the paper needs >= 6; 32 the findings' reference)", min = 3,
                max = 32) int wavelengths,
        @Setting(doc = "SINGLE mode: samples of the outer sum along the view ray", min = 1, max = 64)
        int outerSamples,
        @Setting(doc = "SINGLE mode: samples of the inner sum toward the sun", min = 1, max = 64) int innerSamples,
        @Setting(doc = "aerosol (Mie) density multiplier", min = 0, max = 20) double haze,
        @Setting(doc = "ozone amount multiplier (1 = 300 Dobson units)", min = 0, max = 3) double ozone,
        @Setting(doc = "Mie phase function anisotropy g", min = 0, max = 0.99) double mieAnisotropy,
        @Setting(doc = "ground reflectance seen by multiple scattering", min = 0, max = 1) double groundAlbedo,
        @Setting(doc = "air between eye and surface: AERIAL (scattering) or SIMPLE (the paper's distance fog)")
        Fog fog,
        @Setting(doc = "SIMPLE fog: distance over which 1/e of a surface's light gets through", unit = "m",
                min = 100, max = 1_000_000) double fogDistance) {

    /** How the light scattered toward the eye is computed. */
    public enum Scattering {
        /** Hillaire 2020: single scattering from the transmittance table plus the isotropic transfer Ψ_ms. */
        MULTIPLE,
        /** The paper's first-order scattering, equations 3 and 4, by nested sums. */
        SINGLE
    }

    /** The constants of the air the scattering runs through. */
    public enum Constants {
        /** Earth's atmosphere in metres (Bruneton 2017), with ozone. */
        PHYSICAL,
        /** The paper's normalised height h/H0 with O'Neil's scale depths and hand-tuned K_R, K_M; no ozone. */
        NORMALISED
    }

    /** What the air between the eye and a surface does to the surface's colour. */
    public enum Fog {
        /** Aerial perspective: the light scattered into the ray and the ray's transmittance. */
        AERIAL,
        /** The paper's simple distance fog towards the sky's horizon colour. */
        SIMPLE
    }

    /** Which particles scatter light toward the eye (extinction always counts all of them). */
    public enum Component {
        BOTH,
        RAYLEIGH,
        MIE;

        /** Whether molecules scatter toward the eye. */
        public boolean rayleigh() {
            return this != MIE;
        }

        /** Whether aerosols scatter toward the eye. */
        public boolean mie() {
            return this != RAYLEIGH;
        }
    }

    public static final AtmosphereSettings DEFAULTS = new AtmosphereSettings(
            Scattering.MULTIPLE,
            Constants.PHYSICAL,
            Component.BOTH,
            8,      // wavelengths: above the paper's 6, and SkyView stays within its time budget
            16,     // outer samples: smooth gradients in SINGLE mode's dome
            8,      // inner samples: the sun ray's optical depth varies slowly along it
            1,      // haze: Bruneton's clear-day aerosols
            1,      // ozone: 300 Dobson units, the global mean
            0.8,    // g: Bruneton's and Hillaire's aerosol anisotropy, a bright halo around the sun
            0.3,    // albedo: grass, rock and some snow
            Fog.AERIAL,
            20_000); // fog distance: at 64 km, where the aerial table ends, 4 % of a surface shows through

    public static final SettingsGroup<AtmosphereSettings> SETTINGS =
            SettingsGroup.of("atmosphere", AtmosphereSettings.class, DEFAULTS);

    /** Checks the ranges for records built in code (the {@code --set} parser checks them from the annotations). */
    public AtmosphereSettings {
        if (scattering == null || constants == null || component == null || fog == null) {
            throw new IllegalArgumentException("the scattering model, constants, component and fog must be given");
        }
        requireRange("wavelengths", wavelengths, 3, 32);
        requireRange("outer samples", outerSamples, 1, 64);
        requireRange("inner samples", innerSamples, 1, 64);
        requireRange("haze", haze, 0, 20);
        requireRange("ozone", ozone, 0, 3);
        requireRange("Mie anisotropy", mieAnisotropy, 0, 0.99);
        requireRange("ground albedo", groundAlbedo, 0, 1);
        requireRange("fog distance", fogDistance, 100, 1_000_000);
    }

    private static void requireRange(String name, double value, double min, double max) {
        if (!(value >= min && value <= max)) {
            throw new IllegalArgumentException(name + " must be in [" + min + ", " + max + "], got " + value);
        }
    }

    /** A copy with another scattering model. */
    public AtmosphereSettings withScattering(Scattering s) {
        return new AtmosphereSettings(s, constants, component, wavelengths, outerSamples, innerSamples, haze, ozone,
                mieAnisotropy, groundAlbedo, fog, fogDistance);
    }

    /** A copy with other constants of the air. */
    public AtmosphereSettings withConstants(Constants c) {
        return new AtmosphereSettings(scattering, c, component, wavelengths, outerSamples, innerSamples, haze, ozone,
                mieAnisotropy, groundAlbedo, fog, fogDistance);
    }

    /** A copy with another scattering component. */
    public AtmosphereSettings withComponent(Component c) {
        return new AtmosphereSettings(scattering, constants, c, wavelengths, outerSamples, innerSamples, haze, ozone,
                mieAnisotropy, groundAlbedo, fog, fogDistance);
    }

    /** A copy with another number of wavelengths. */
    public AtmosphereSettings withWavelengths(int count) {
        return new AtmosphereSettings(scattering, constants, component, count, outerSamples, innerSamples, haze,
                ozone, mieAnisotropy, groundAlbedo, fog, fogDistance);
    }

    /** A copy with {@code count} samples in each of the single-scattering sums, outer and inner. */
    public AtmosphereSettings withSamples(int count) {
        return new AtmosphereSettings(scattering, constants, component, wavelengths, count, count, haze, ozone,
                mieAnisotropy, groundAlbedo, fog, fogDistance);
    }

    /** A copy with another fog and fog distance, m. */
    public AtmosphereSettings withFog(Fog f, double distanceM) {
        return new AtmosphereSettings(scattering, constants, component, wavelengths, outerSamples, innerSamples,
                haze, ozone, mieAnisotropy, groundAlbedo, f, distanceM);
    }
}

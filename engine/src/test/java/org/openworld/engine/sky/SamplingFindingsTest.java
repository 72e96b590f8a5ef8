package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.openworld.engine.colour.ImageComparison;
import org.openworld.engine.gl.Image;
import org.openworld.engine.sky.AtmosphereSettings.Scattering;
import org.openworld.engine.sky.SkyPicture.Sun;

/**
 * The paper's findings on sampling (3.1), measured on the CPU sky ({@link SkyPicture}): mean CIEDE2000 over the sun's
 * half of the dome against a finely sampled reference, at noon and at sunset; 2 is a just-noticeable difference.
 * The paper says 6 wavelengths and 2 samples in each sum suffice. Measured: 6 wavelengths do for the default
 * (multiple-scattering) sky and for the paper's single scattering at noon, but the paper's sunset needs 8; the
 * sums need 16 samples with physical constants, 2 are far off (docs/sky.md says why); with the paper's normalised
 * constants 4 are enough.
 */
class SamplingFindingsTest {

    private static final double NOTICEABLE = 2;
    private static final AtmosphereSettings SINGLE = AtmosphereSettings.DEFAULTS.withScattering(Scattering.SINGLE);

    @Test
    void sixWavelengthsAreEnoughForTheDefaultSkyAndThreeAreNot() {
        for (Sun sun : new Sun[] {Sun.NOON, Sun.SUNSET}) {
            AtmosphereSettings base = AtmosphereSettings.DEFAULTS;
            Image reference = SkyPicture.render(base.withWavelengths(SkyPicture.REFERENCE_WAVELENGTHS), sun);
            assertAbove(reference, base.withWavelengths(3), sun, "3 wavelengths, multiple scattering");
            assertBelow(reference, base.withWavelengths(6), sun, "6 wavelengths, multiple scattering");
        }
    }

    @Test
    void thePapersSingleScatteringSunsetNeedsEightWavelengths() {
        for (Sun sun : new Sun[] {Sun.NOON, Sun.SUNSET}) {
            Image reference = SkyPicture.render(SINGLE.withWavelengths(SkyPicture.REFERENCE_WAVELENGTHS), sun);
            assertAbove(reference, SINGLE.withWavelengths(3), sun, "3 wavelengths, single scattering");
            assertBelow(reference, SINGLE.withWavelengths(8), sun, "8 wavelengths, single scattering");
        }
        Image sunset = SkyPicture.render(SINGLE.withWavelengths(SkyPicture.REFERENCE_WAVELENGTHS), Sun.SUNSET);
        assertAbove(sunset, SINGLE.withWavelengths(6), Sun.SUNSET, "6 wavelengths, single scattering");
        Image noon = SkyPicture.render(SINGLE.withWavelengths(SkyPicture.REFERENCE_WAVELENGTHS), Sun.NOON);
        assertBelow(noon, SINGLE.withWavelengths(6), Sun.NOON, "6 wavelengths, single scattering");
    }

    @Test
    void sixteenSamplesPerSumAreEnoughAndTwoAreNot() {
        for (Sun sun : new Sun[] {Sun.NOON, Sun.SUNSET}) {
            Image reference = SkyPicture.render(SINGLE.withSamples(SkyPicture.REFERENCE_SAMPLES), sun);
            assertAbove(reference, SINGLE.withSamples(1), sun, "1 sample per sum");
            assertAbove(reference, SINGLE.withSamples(2), sun, "2 samples per sum");
            assertBelow(reference, SINGLE.withSamples(16), sun, "16 samples per sum");
        }
    }

    @Test
    void withThePapersNormalisedConstantsFourSamplesAreEnoughAndOneIsNot() {
        // The density falls by e^4 across the shell, not e^12.5: the sums converge far sooner (docs/sky.md).
        AtmosphereSettings paper = SINGLE.withConstants(AtmosphereSettings.Constants.NORMALISED);
        for (Sun sun : new Sun[] {Sun.NOON, Sun.SUNSET}) {
            Image reference = SkyPicture.render(paper.withSamples(SkyPicture.REFERENCE_SAMPLES), sun);
            assertAbove(reference, paper.withSamples(1), sun, "1 sample per sum, normalised constants");
            assertBelow(reference, paper.withSamples(4), sun, "4 samples per sum, normalised constants");
        }
    }

    private static double deltaE(Image reference, AtmosphereSettings settings, Sun sun, String what) {
        double mean = ImageComparison.of(reference, SkyPicture.render(settings, sun)).meanDeltaE();
        System.out.printf(Locale.ROOT, "sampling findings: %s at %s: mean dE00 %.2f%n", what, sun.name(), mean);
        return mean;
    }

    private static void assertBelow(Image reference, AtmosphereSettings settings, Sun sun, String what) {
        double mean = deltaE(reference, settings, sun, what);
        assertTrue(mean < NOTICEABLE, what + " at " + sun.name() + ": mean dE00 " + mean + " from the reference");
    }

    private static void assertAbove(Image reference, AtmosphereSettings settings, Sun sun, String what) {
        double mean = deltaE(reference, settings, sun, what);
        assertTrue(mean > NOTICEABLE, what + " at " + sun.name() + ": mean dE00 " + mean + " from the reference, "
                + "expected a noticeable difference");
    }
}

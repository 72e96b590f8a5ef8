package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.openworld.engine.environment.Exposure;

/** The exposure law with its night floor and the Purkinje share (no GL). */
class AdaptationTest {

    /** How bright a white surface is shown in the light e: B(e) = e · exposure. */
    static double shown(double e) {
        return e * Adaptation.exposure(e, 0);
    }

    /** Where the square root and the night floor meet: √E = B₀ E^k, E = B₀^(1 / (1/2 − k)). */
    static final double MEET = Math.pow(Adaptation.NIGHT_FLOOR, 1 / (0.5 - Adaptation.NIGHT_SLOPE));

    @Test
    void theDayKeepsTheSquareRootLaw() {
        // noon (about 1), the README's 17:30 (0.15), the sun on the horizon (0.008): exposure = 1 / √E exactly,
        // so no daylight picture changes
        for (double e : new double[] {1, 0.15, 0.008, 1.001 * MEET}) {
            assertEquals(1 / Math.sqrt(e), Adaptation.exposure(e, 0), 1e-12 / Math.sqrt(e), "E = " + e);
        }
        // 0.008: the sun on the horizon (above) must still be day; 1e-3: the floor must take over within the civil
        // twilight (3e-4 at -4.6°)
        assertTrue(MEET < 0.008 && MEET > 1e-3, "the floor takes over after sunset: " + MEET);
    }

    @Test
    void theNightHasAFloorThatFallsSlowly() {
        // the light of the night falls 10 decades from sunset to a moonless night (the sky tables: 3e-4 at -4.6
        // degrees, 5e-7 at -10; the airglow 6e-9): a white surface is shown dimmer by 10^-k a decade, no faster
        for (double e = 0.999 * MEET; e > 1e-11; e /= 10) {
            // doubles: ratios of powers, exact to ~1e-15; 1e-9 and 1e-12 are loose round-off bands
            assertEquals(Math.pow(10, -Adaptation.NIGHT_SLOPE), shown(e / 10) / shown(e), 1e-9, "E = " + e);
        }
        // a ground of albedo 0.2 under a moonless sky is shown at 0.2 B; the tone curve's toe maps that to 0.21 of
        // it, and one 8-bit level of sRGB is 1/255/12.92 = 3e-4 of linear light: the ground must stay above a few
        double ground = 0.2 * shown(NightLight.SKY) * 0.21;
        // three 8-bit levels: the darkest a surface may be and still read as ground, not black
        assertTrue(ground > 3 * 3.04e-4, "moonless ground, linear display light " + ground);
        // and never brighter than the day's picture of the same light would be at dusk
        assertTrue(shown(MEET) > shown(1e-9), "the night stays darker than dusk");
    }

    @Test
    void moreLightIsNeverShownDarker() {
        double previous = 0;
        for (double e = 1e-12; e < 10; e *= 1.1) {
            double b = shown(e);
            assertTrue(b >= previous, "B(" + e + ") = " + b + " below " + previous);
            previous = b;
        }
    }

    @Test
    void compensationCountsStops() {
        assertEquals(2 * Adaptation.exposure(1e-6, 0), Adaptation.exposure(1e-6, 1), 1e-9);
        Exposure fixed = SkySystem.exposure(new SkySettings(46, 10, 2, false, 3), new Vector3d(1e-7));
        // float scale (24-bit mantissa): 1e-6 relative
        assertEquals(4, fixed.scale(), 1e-6, "auto-exposure off: noon's, times two stops");
        assertEquals(0, fixed.scotopic(), "and no night vision");
    }

    @Test
    void theRodsTakeOverAtNight() {
        // Jensen et al.'s range: all cones above 10^0.6 cd/m2, all rods below 10^-2, half at the middle 10^-0.7
        double day = 10 * Math.PI / (Adaptation.ADAPTING_GREY * Adaptation.SUN_LUX);   // 10 cd/m2 adapting
        double night = 1e-3 * Math.PI / (Adaptation.ADAPTING_GREY * Adaptation.SUN_LUX); // 1e-3 cd/m2
        double middle = Math.pow(10, -0.7) * Math.PI / (Adaptation.ADAPTING_GREY * Adaptation.SUN_LUX);
        assertEquals(0, Adaptation.scotopicShare(day), 1e-12);
        assertEquals(1, Adaptation.scotopicShare(night), 1e-12);
        assertEquals(0.5, Adaptation.scotopicShare(middle), 1e-9);
        // the sky's own lights: the sun on the horizon (0.008) is day; the nautical twilight (5e-7, the sun 10
        // degrees down) and a moonless night are the rods'
        assertEquals(0, Adaptation.scotopicShare(0.008), 1e-12);
        assertEquals(1, Adaptation.scotopicShare(5e-7), 1e-12);
        double previous = 0;
        for (double e = 1e-3; e > 1e-8; e /= 1.5) {
            double s = Adaptation.scotopicShare(e);
            assertTrue(s >= previous, "the share grows as the light falls");
            previous = s;
        }
    }
}

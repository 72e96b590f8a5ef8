package org.openworld.engine.sky;

import org.joml.Vector3dc;

/**
 * How the picture adapts to the light of the moment, as an eye or a camera does: the exposure law with its night
 * floor, and the share of rod vision that turns the night blue and grey (the Purkinje shift).
 *
 * <p><b>Exposure.</b> E is the luminance of the light on level ground (sun and sky, moon and night sky), display
 * units (1 = the sun above the air). B(E) = E · exposure is how bright a white surface in that light is shown:
 * <pre>
 *   B(E) = max(√E, B_NIGHT · E^k)          exposure = B(E) / E
 * </pre>
 * By day the square root: half adaptation, so dusk is darker than noon but readable (noon's light, about 1, is shown
 * as 1). Below the light of a sun 1° under the horizon (E = 0.004, where the two terms meet) the night floor takes
 * over: the adaptation is nearly complete (1 − k = 97 %), so the picture of a white surface falls only by
 * 10^−k = 0.93 per decade of light, from 6 % of noon's in the civil twilight (E = 3·10⁻⁴, the sun 4.6° down) to 4.8 %
 * in the nautical twilight (10⁻⁷) and 4.3 % under the airglow of a moonless night (6·10⁻⁹), where the square root
 * alone would show a white surface at 10⁻⁴ of noon's, black after the tone curve's toe (ACES maps a small x to
 * 0.21 x: the ground, a fifth as bright as white, ends below one 8-bit level). That is
 * what a camera's automatic exposure does until its longest exposure, and roughly what an eye's brightness
 * perception does (its adaptation spans ten decades; what it keeps of the night's darkness is its dimness, its lost
 * colour and its blue cast, below).
 *
 * <p><b>Purkinje shift</b> (Jensen, Durand, Stark, Premože, Dorsey and Shirley 2001, "A physically-based night sky
 * model", SIGGRAPH; its tone mapping). Rods, which see no colour and are most sensitive at 507 nm against the cones' 555 nm, take
 * over as the light falls. Their share s is set by the adaptation luminance L_a (cd/m²) on a log scale:
 * <pre>
 *   x = (log10 L_a + 2) / 2.6      s = 1 − smoothstep(x)   (s = 1 below 0.01 cd/m², 0 above 4 cd/m²)
 *   L_a = 0.18 · E · E_SUN_LUX / π  (a grey of 18 % under the light, E_SUN_LUX lux for E = 1)
 * </pre>
 * {@code shaders/common/color.glsl} mixes each pixel's colour towards the rods' grey-blue by s: the scotopic
 * luminance V = Y (1.33 (1 + (Y + Z) / X) − 1.68) of its CIE XYZ (Larson, Rushmeier and Piatko's fit, which Jensen
 * et al. use), divided by D65 white's 2.573 so that daylight-coloured light keeps its luminance, shown with the
 * chromaticity (0.25, 0.25) Jensen et al. give the night's blue. s is per frame, from the scene's light rather than
 * per pixel, so a colour scaled is shifted the same way (V is of degree 1 in the colour) and the shift does not
 * break the exposure. Cost: a 3 × 3 product and a division per pixel in the tone mapping every shader does last,
 * skipped (a branch on a uniform) while s is 0, so daylight pictures are unchanged to the bit.
 */
public final class Adaptation {

    /** B of a white surface under the night floor at E = 1, display units: 4.8 % of noon's at E = 10^-7. */
    static final double NIGHT_FLOOR = 0.075;
    /** How fast the night floor falls with the light: 10^-k per decade of E (0.93). */
    static final double NIGHT_SLOPE = 0.03;
    /** The least light the law adapts to, display units: 1/1000 of a moonless night's airglow. */
    static final double MIN_LIGHT = 1e-12;
    /**
     * The sun's illuminance above the air at normal incidence, lux: display unit 1 in photometric terms (Darula,
     * Kittler and Gueymard 2005, "Reference luminous solar constant and solar luminance for illuminance
     * calculations": 133.8 klx).
     */
    public static final double SUN_LUX = 133_800;
    /** The reflectance of the grey the eye is taken to adapt to: the photographer's 18 %. */
    static final double ADAPTING_GREY = 0.18;
    /** Jensen et al.'s mesopic range: log10 of the adaptation luminance (cd/m²) where the rods take all, and its width. */
    static final double SCOTOPIC_LOG = -2;
    static final double MESOPIC_DECADES = 2.6;

    private Adaptation() {
    }

    /** Rec. 709 luminance of a linear sRGB light, the E of the class comment. */
    public static double luminance(Vector3dc rgb) {
        return 0.2126 * rgb.x() + 0.7152 * rgb.y() + 0.0722 * rgb.z();
    }

    /** The exposure for the ground light {@code e} (display units), times the compensation in stops. */
    public static double exposure(double e, double compensationEv) {
        double light = Math.max(e, MIN_LIGHT);
        double shown = Math.max(Math.sqrt(light), NIGHT_FLOOR * Math.pow(light, NIGHT_SLOPE));
        return shown / light * Math.pow(2, compensationEv);
    }

    /** The adaptation luminance for the ground light {@code e}, cd/m². */
    public static double adaptationLuminance(double e) {
        return ADAPTING_GREY * e * SUN_LUX / Math.PI;
    }

    /** The rods' share s (0 by day, 1 at night) for the ground light {@code e}, display units. */
    public static double scotopicShare(double e) {
        double x = (Math.log10(Math.max(adaptationLuminance(e), 1e-30)) - SCOTOPIC_LOG) / MESOPIC_DECADES;
        double t = Math.min(Math.max(x, 0), 1);
        return 1 - t * t * (3 - 2 * t);
    }
}

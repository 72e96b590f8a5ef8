package org.openworld.engine.water;

import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Settings of the water, keys {@code water.*}.
 *
 * @param level      height of the water plane, metres (0: sea level, docs/design.md's convention)
 * @param method     FRESNEL (the default: a clipped reflection and the refracted scene, mixed by the Fresnel term)
 *                   or STENCIL (the paper's four steps of section 3.3, for figure 13)
 * @param alpha      the STENCIL method's water alpha, the paper's "reflectivity": 0 shows the ground through the
 *                   water, 1 only the reflection (figure 13's series)
 * @param reflection the reflection pass's resolution: HALF of the picture's (the default: the ripples blur it
 *                   anyway, and it costs a quarter of the pixels) or FULL
 * @param clarity    how far one sees into the water, metres: the distance over which the water's extinction, beyond
 *                   pure water's own absorption, takes away 1 − 1/e of the light (a clear lake 10–20, a harbour 2)
 * @param wind       wind speed over the water, m/s, which sets the ripples' wavelengths and their slopes (Cox and
 *                   Munk: mean square slope 0.003 + 0.00512 · wind)
 * @param windDirection where the wind blows towards, degrees clockwise from north
 */
public record WaterSettings(
        @Setting(doc = "height of the water plane", unit = "m", min = -10000, max = 10000) double level,
        @Setting(doc = "FRESNEL (clipped reflection + refraction) or STENCIL (the paper's section 3.3)") Method method,
        @Setting(doc = "the STENCIL method's water alpha: 0 ground through the water, 1 reflection only", min = 0,
                max = 1) double alpha,
        @Setting(doc = "reflection pass resolution: HALF or FULL") Resolution reflection,
        @Setting(doc = "distance that takes 1 - 1/e of the light seen through the water", unit = "m", min = 0.1,
                max = 1000) double clarity,
        @Setting(doc = "wind speed over the water (ripple size and steepness)", unit = "m/s", min = 0.5, max = 20)
        double wind,
        @Setting(doc = "direction the wind blows towards, clockwise from north", unit = "deg", min = 0, max = 360)
        double windDirection) {

    /** How the water is drawn. */
    public enum Method {
        /** Reflection pass clipped at the water, the refracted scene with depth, mixed by the Fresnel term. */
        FRESNEL,
        /** The paper's four steps: stencil mask, mirrored scene, a full-screen quad blended by destination alpha. */
        STENCIL
    }

    /** The reflection pass's size relative to the picture. */
    public enum Resolution {
        HALF(2),
        FULL(1);

        private final int divisor;

        Resolution(int divisor) {
            this.divisor = divisor;
        }

        /** The reflection's side for a picture side of {@code pixels}. */
        public int of(int pixels) {
            return Math.max(1, pixels / divisor);
        }
    }

    public static final WaterSettings DEFAULTS = new WaterSettings(0, Method.FRESNEL, 0.5, Resolution.HALF, 8, 5, 60);

    public static final SettingsGroup<WaterSettings> SETTINGS = SettingsGroup.of("water", WaterSettings.class, DEFAULTS);

    public WaterSettings {
        if (method == null || reflection == null) {
            throw new IllegalArgumentException("water method and reflection resolution must be given");
        }
    }

    /** Cox and Munk's (1954) RMS slope of a clean sea surface in this wind: √(0.003 + 0.00512 · wind). */
    public double rmsSlope() {
        return Math.sqrt(0.003 + 0.00512 * wind);
    }
}

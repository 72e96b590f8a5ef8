package org.openworld.engine.antialias;

import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Settings of the picture's anti-aliasing ({@link Fxaa}).
 *
 * @param method   OFF: the scene target is the picture, every edge a staircase; FXAA: one post pass finds the edges
 *                 by their contrast and blends each pixel with its neighbour across the edge by the share of the
 *                 pixel the edge should cover
 * @param subpixel how much a pixel that stands out from all its neighbours (a one-pixel glint, a thin line) is
 *                 blended into them: 0 keeps it, 1 blends it most (FXAA's "subpix"); more is steadier in motion and
 *                 softer
 */
public record AntialiasSettings(
        @Setting(doc = "anti-aliasing of the picture: off or fxaa (a post pass over the scene's edges)")
        Method method,
        @Setting(doc = "FXAA: how much a pixel standing out from all its neighbours is blended into them", min = 0,
                max = 1) double subpixel) {

    /** How the picture is anti-aliased. */
    public enum Method {
        /** None: the scene target is shown as drawn. */
        OFF,
        /** Fast approximate anti-aliasing (Lottes 2009), one full-screen pass after the scene. */
        FXAA
    }

    /** FXAA's own default amount of sub-pixel blending (FXAA 3.11's {@code fxaaQualitySubpix}). */
    public static final AntialiasSettings DEFAULTS = new AntialiasSettings(Method.FXAA, 0.75);

    public static final SettingsGroup<AntialiasSettings> GROUP =
            SettingsGroup.of("antialias", AntialiasSettings.class, DEFAULTS);

    /** Whether a pass runs at all. */
    public boolean enabled() {
        return method != Method.OFF;
    }
}

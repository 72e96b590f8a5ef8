package org.openworld.engine.sky;

import org.joml.Vector3dc;

/** Helpers shared by the sky tests. */
final class SkyColours {

    private SkyColours() {
    }

    /** Relative luminance of linear sRGB (Rec. 709 weights). */
    static double luminance(Vector3dc rgb) {
        return 0.2126 * rgb.x() + 0.7152 * rgb.y() + 0.0722 * rgb.z();
    }

    /** Tables for the defaults with another scattering model and component. */
    static AtmosphereTables tables(AtmosphereSettings.Scattering scattering, AtmosphereSettings.Component component) {
        return AtmosphereTables.build(AtmosphereSettings.DEFAULTS.withScattering(scattering).withComponent(component));
    }
}

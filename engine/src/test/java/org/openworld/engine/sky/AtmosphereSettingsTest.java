package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.openworld.engine.settings.SettingsGroup;

class AtmosphereSettingsTest {

    @Test
    void keysAndDefaults() {
        List<String> keys = AtmosphereSettings.SETTINGS.keys().stream().map(SettingsGroup.Key::key).toList();
        assertEquals(List.of("atmosphere.scattering", "atmosphere.constants", "atmosphere.component",
                "atmosphere.wavelengths", "atmosphere.outer-samples", "atmosphere.inner-samples", "atmosphere.haze",
                "atmosphere.ozone", "atmosphere.mie-anisotropy", "atmosphere.ground-albedo", "atmosphere.fog",
                "atmosphere.fog-distance"), keys);
        assertEquals(AtmosphereSettings.Scattering.MULTIPLE, AtmosphereSettings.DEFAULTS.scattering());
        assertEquals(AtmosphereSettings.Constants.PHYSICAL, AtmosphereSettings.DEFAULTS.constants());
        assertEquals(AtmosphereSettings.Fog.AERIAL, AtmosphereSettings.DEFAULTS.fog());
        assertEquals(8, AtmosphereSettings.DEFAULTS.wavelengths());
    }

    @Test
    void outOfRangeValuesAreRejected() {
        AtmosphereSettings d = AtmosphereSettings.DEFAULTS;
        assertThrows(IllegalArgumentException.class, () -> d.withWavelengths(2));
        assertThrows(IllegalArgumentException.class, () -> d.withWavelengths(33));
        assertThrows(IllegalArgumentException.class, () -> new AtmosphereSettings(d.scattering(), d.constants(),
                d.component(), 8, 16, 8, 1, 1, 1.0, 0.3, d.fog(), d.fogDistance()));
        assertThrows(IllegalArgumentException.class, () -> d.withFog(AtmosphereSettings.Fog.SIMPLE, 10));
        assertEquals(32, d.withWavelengths(32).wavelengths());
        assertEquals(1, d.withSamples(1).outerSamples());
        assertThrows(IllegalArgumentException.class, () -> d.withSamples(0));
    }
}

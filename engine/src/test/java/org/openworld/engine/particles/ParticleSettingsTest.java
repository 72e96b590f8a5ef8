package org.openworld.engine.particles;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsException;

class ParticleSettingsTest {

    @Test
    void gravityIsWhatDragBalancesAtTheFallSpeed() {
        ParticleSettings s = new ParticleSettings(10, 1.4, 3, 0.2, 0.02, 40, 0.3);
        // doubles: quotients of the settings, equal to round-off
        assertEquals(1.4, SnowMotion.terminalVelocity(s.gravity(), s.drag()), 1e-12);
        assertEquals(0.2, s.brownian() / Math.sqrt(2 * s.drag()), 1e-12, "the small-step spread is the turbulence");
    }

    @Test
    void theCountHasANamedRange() {
        Settings settings = new Settings(List.of(ParticleSettings.SETTINGS));
        settings.set("particles.count", "1000000");
        assertEquals(1_000_000, settings.get(ParticleSettings.class).count(), "a million must run");
        SettingsException e = assertThrows(SettingsException.class, () -> settings.set("particles.count", "0"));
        assertTrue(e.getMessage().contains("particles.count"), e.getMessage());
    }
}

package org.openworld.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsException;

/** The render scale's sizes and range, without GL. */
class ScaledSceneTest {

    @Test
    void theSceneTargetIsThePictureTimesTheScaleRoundedAndAtLeastOnePixel() {
        assertEquals(896, ScaledScene.scaled(1280, 0.7));
        assertEquals(504, ScaledScene.scaled(720, 0.7));
        assertEquals(1280, ScaledScene.scaled(1280, 1));
        assertEquals(1, ScaledScene.scaled(1, 0.25));
    }

    @Test
    void aScaleOutsideAQuarterToOneOrTwoIsRefusedNamingTheRange() {
        Settings settings = Engine.settingsFor(List.of());
        settings.set("engine.render-scale", "0.25");
        assertEquals(0.25, settings.get(EngineSettings.class).renderScale());
        settings.set("engine.render-scale", "2");
        assertEquals(2, settings.get(EngineSettings.class).renderScale());
        SettingsException e = assertThrows(SettingsException.class, () -> settings.set("engine.render-scale", "1.5"));
        assertTrue(e.getMessage().contains("engine.render-scale") && e.getMessage().contains("must be 2"),
                e.getMessage());
        e = assertThrows(SettingsException.class, () -> settings.set("engine.render-scale", "3"));
        assertTrue(e.getMessage().contains("0.25 .. 2"), e.getMessage());
    }
}

package org.openworld.engine.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.input.InputState;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsException;

class CameraSettingsTest {

    @Test
    void everyKeyIsUnderCameraAndItsDefaultReadsBack() {
        Settings settings = new Settings(List.of(CameraSystem.SETTINGS));
        assertEquals(List.of("camera.fov", "camera.fly-speed", "camera.boost", "camera.acceleration",
                "camera.damping", "camera.mouse-sensitivity", "camera.look-smoothing", "camera.turn-speed",
                "camera.walk-speed", "camera.run-factor", "camera.eye-height", "camera.step-smoothing",
                "camera.mode"), settings.keys());
        settings.asText().forEach(settings::set);
        assertEquals(CameraSettings.DEFAULTS, settings.get(CameraSettings.class));
        assertEquals("fly", settings.text("camera.mode"));
        settings.set("camera.mode", "walk");
        assertEquals(CameraMode.WALK, settings.get(CameraSettings.class).mode());
        assertThrows(SettingsException.class, () -> settings.set("camera.fov", "200"));
    }

    @Test
    void theSystemDeclaresItsAccess() {
        SystemSpec spec = new CameraSystem().spec();
        assertEquals("camera", spec.name());
        assertTrue(spec.reads().containsAll(List.of(InputState.class, HeightField.class, Settings.class)));
        assertEquals(java.util.Set.of(Camera.class), spec.writes());
        assertTrue(spec.passes().isEmpty());
    }
}

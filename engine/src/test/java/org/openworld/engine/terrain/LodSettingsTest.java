package org.openworld.engine.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.openworld.engine.settings.SettingsGroup;

class LodSettingsTest {

    @Test
    void keysAndDefaults() {
        List<String> keys = LodSettings.SETTINGS.keys().stream().map(SettingsGroup.Key::key).toList();
        assertEquals(List.of("lod.patch-vertices", "lod.base-resolution", "lod.mode"), keys);
        assertEquals(64, LodSettings.DEFAULTS.cells());
        assertEquals(LodMode.QUADTREE, LodSettings.DEFAULTS.mode());
    }

    @Test
    void onlyThePatchSizesWithPatternsAreAccepted() {
        assertEquals(32, new LodSettings(33, 100, LodMode.FLAT_GRID).cells());
        assertThrows(IllegalArgumentException.class, () -> new LodSettings(48, 100, LodMode.QUADTREE));
        assertThrows(IllegalArgumentException.class, () -> new LodSettings(65, 0, LodMode.QUADTREE));
    }
}

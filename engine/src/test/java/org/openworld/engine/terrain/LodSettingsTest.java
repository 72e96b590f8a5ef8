package org.openworld.engine.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.openworld.engine.core.Pass;
import org.openworld.engine.settings.SettingsGroup;

class LodSettingsTest {

    @Test
    void keysAndDefaults() {
        List<String> keys = LodSettings.SETTINGS.keys().stream().map(SettingsGroup.Key::key).toList();
        assertEquals(List.of("lod.patch-vertices", "lod.base-resolution", "lod.mode", "lod.reflection-coarsening"), keys);
        assertEquals(64, LodSettings.DEFAULTS.cells());
        assertEquals(LodMode.QUADTREE, LodSettings.DEFAULTS.mode());
    }

    @Test
    void theReflectionPassIsCoarserByTheGivenLevels() {
        LodSettings twoLevels = new LodSettings(65, 128, LodMode.QUADTREE, 2);
        assertEquals(128, twoLevels.baseResolution(Pass.MAIN));
        assertEquals(32, twoLevels.baseResolution(Pass.REFLECTION));
        assertEquals(128, new LodSettings(65, 128, LodMode.QUADTREE, 0).baseResolution(Pass.REFLECTION));
    }

    @Test
    void onlyThePatchSizesWithPatternsAreAccepted() {
        assertEquals(32, new LodSettings(33, 100, LodMode.FLAT_GRID, 1).cells());
        assertThrows(IllegalArgumentException.class, () -> new LodSettings(48, 100, LodMode.QUADTREE, 1));
        assertThrows(IllegalArgumentException.class, () -> new LodSettings(65, 0, LodMode.QUADTREE, 1));
    }
}

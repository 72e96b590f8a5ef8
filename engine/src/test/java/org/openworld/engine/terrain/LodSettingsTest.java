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
        assertEquals(List.of("lod.patch-vertices", "lod.base-resolution", "lod.mode", "lod.reflection-coarsening",
                "lod.shadow-coarsening"), keys);
        assertEquals(64, LodSettings.DEFAULTS.cells());
        assertEquals(LodMode.QUADTREE, LodSettings.DEFAULTS.mode());
    }

    @Test
    void theReflectionAndShadowPassesAreCoarserByTheirLevels() {
        LodSettings coarser = new LodSettings(65, 128, LodMode.QUADTREE, 2, 3);
        assertEquals(128, coarser.baseResolution(Pass.MAIN));
        assertEquals(32, coarser.baseResolution(Pass.REFLECTION));
        assertEquals(16, coarser.baseResolution(Pass.SHADOW));
        assertEquals(128, new LodSettings(65, 128, LodMode.QUADTREE, 0, 0).baseResolution(Pass.REFLECTION));
        assertEquals(128, new LodSettings(65, 128, LodMode.QUADTREE, 0, 0).baseResolution(Pass.SHADOW));
    }

    @Test
    void onlyThePatchSizesWithPatternsAreAccepted() {
        assertEquals(32, new LodSettings(33, 100, LodMode.FLAT_GRID, 1, 1).cells());
        assertThrows(IllegalArgumentException.class, () -> new LodSettings(48, 100, LodMode.QUADTREE, 1, 1));
        assertThrows(IllegalArgumentException.class, () -> new LodSettings(65, 0, LodMode.QUADTREE, 1, 1));
    }
}

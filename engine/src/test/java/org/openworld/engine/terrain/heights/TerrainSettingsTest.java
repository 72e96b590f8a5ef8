package org.openworld.engine.terrain.heights;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.openworld.engine.settings.SettingsException;

/** The terrain settings' keys and the rules across components. */
class TerrainSettingsTest {

    @Test
    void defaultsAreValidAndKeysAreKebabCase() {
        TerrainSettings d = TestTerrain.settings();
        assertEquals(TerrainSettings.DEFAULTS, d);
        assertEquals(4096, d.extent());
        assertFalse(d.imports());
        assertTrue(TestTerrain.settings("terrain.import-file=maps/alps.png").imports());
        assertEquals(0.3, TestTerrain.settings("terrain.sea-fraction=0.3").seaFraction());
    }

    @Test
    void theWorldIsUnboundedUnlessAMapIsImported() {
        assertEquals(TerrainSettings.World.UNBOUNDED, TestTerrain.settings().world());
        assertEquals(TerrainSettings.World.TILE, TestTerrain.settings("terrain.world=tile").world());
        // an import is one tile whichever order the keys come in, and stays one if the world is named after it
        assertEquals(TerrainSettings.World.TILE, TestTerrain.settings("terrain.import-file=maps/alps.png").world());
        assertEquals(TerrainSettings.World.TILE,
                TestTerrain.settings("terrain.world=unbounded", "terrain.import-file=maps/alps.png").world());
        assertEquals(TerrainSettings.World.TILE,
                TestTerrain.settings("terrain.import-file=maps/alps.png", "terrain.world=unbounded").world());
        // without the import, the unbounded world can be named again
        assertEquals(TerrainSettings.World.UNBOUNDED, TestTerrain.settings("terrain.import-file=maps/alps.png",
                "terrain.import-file=", "terrain.world=unbounded").world());
    }

    @Test
    void sizeMustBeAPowerOfTwo() {
        var e = assertThrows(SettingsException.class, () -> TestTerrain.settings("terrain.size=1000"));
        assertTrue(e.getMessage().contains("terrain.size") && e.getMessage().contains("power of two"), e.getMessage());
        assertEquals(1024, TestTerrain.settings("terrain.size=1024").size());
    }

    @Test
    void shortestWavelengthMustBeBelowTheLongest() {
        var e = assertThrows(SettingsException.class, () -> TestTerrain.settings("terrain.min-wavelength=3000"));
        assertTrue(e.getMessage().contains("terrain.min-wavelength") && e.getMessage().contains("less than"),
                e.getMessage());
        assertThrows(SettingsException.class, () -> TestTerrain.settings("terrain.max-wavelength=4"));
    }

    @Test
    void cutOffsMustOverlapWhatTheGridHolds() {
        var e = assertThrows(SettingsException.class,
                () -> TestTerrain.settings("terrain.min-wavelength=0.5", "terrain.max-wavelength=3"));
        assertTrue(e.getMessage().contains("two samples"), e.getMessage());
    }

    @Test
    void snowMustStartBelowWhereItIsCertain() {
        var e = assertThrows(SettingsException.class, () -> TestTerrain.settings("terrain.snow-base=0.9"));
        assertTrue(e.getMessage().contains("terrain.snow-base"), e.getMessage());
    }
}

package org.openworld.engine.terrain.lod;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.settings.SettingsGroup;
import org.openworld.engine.terrain.TerrainSystem;

class LodSettingsTest {

    @Test
    void keysAndDefaults() {
        List<String> keys = LodSettings.SETTINGS.keys().stream().map(SettingsGroup.Key::key).toList();
        assertEquals(List.of("lod.patch-vertices", "lod.rule", "lod.pixel-error",
                "lod.base-resolution", "lod.mode", "lod.reflection-coarsening", "lod.shadow-coarsening", "lod.morph"),
                keys);
        assertTrue(LodSettings.DEFAULTS.morph(), "geomorphing is on by default (see LodSettings#morph)");
        assertEquals(32, LodSettings.DEFAULTS.cells());
        assertEquals(LodMode.QUADTREE, LodSettings.DEFAULTS.mode());
        assertEquals(LodRule.SCREEN_ERROR, LodSettings.DEFAULTS.rule());
    }

    @Test
    void theReflectionAndShadowPassesAreCoarserByTheirLevels() {
        LodSettings coarser = new LodSettings(65, LodRule.PAPER, 2, 128, LodMode.QUADTREE, 2, 3, true);
        assertEquals(128, coarser.baseResolution(Pass.MAIN));
        assertEquals(32, coarser.baseResolution(Pass.REFLECTION));
        assertEquals(16, coarser.baseResolution(Pass.SHADOW));
        LodSettings none = new LodSettings(65, LodRule.PAPER, 2, 128, LodMode.QUADTREE, 0, 0, true);
        assertEquals(128, none.baseResolution(Pass.REFLECTION));
        assertEquals(128, none.baseResolution(Pass.SHADOW));
    }

    /**
     * The paper's rule is B in every pass, coarser in the reflection's and the sun's; the screen-error rule is the
     * pixel bound of the camera and target given: through an orthographic box 2048 m wide on 2048² pixels (1 m a
     * pixel), an error of exactly the bound is fine enough at any distance, one a little larger nowhere. (The sun's
     * pass gives it the viewer's camera, in {@link TerrainSystem}.)
     */
    @Test
    void eachPassGetsItsOwnLimit() {
        LodSettings paper = new LodSettings(65, LodRule.PAPER, 2, 128, LodMode.QUADTREE, 1, 2, true);
        ViewCamera box = new ViewCamera(new Matrix4f(), new Matrix4f().ortho(-1024, 1024, -1024, 1024, 0, 500),
                new Vector3f(), 0, 500);
        assertEquals(DetailLimit.paper(32), paper.limit(Pass.SHADOW, box, 2048, 2048));
        assertEquals(DetailLimit.paper(64), paper.limit(Pass.REFLECTION, box, 2048, 2048));
        LodSettings screen = new LodSettings(65, LodRule.SCREEN_ERROR, 2, 128, LodMode.QUADTREE, 1, 2, true);
        DetailLimit main = screen.limit(Pass.MAIN, box, 2048, 2048);
        assertTrue(main.fineEnough(3, 2, 1));
        assertTrue(main.fineEnough(3, 2, 1e5));
        assertFalse(main.fineEnough(3, 2.01, 1e5));
    }

    @Test
    void onlyThePatchSizesWithPatternsAreAccepted() {
        assertEquals(16, new LodSettings(17, LodRule.PAPER, 2, 100, LodMode.FLAT_GRID, 1, 1, true).cells());
        assertEquals(32, new LodSettings(33, LodRule.PAPER, 2, 100, LodMode.FLAT_GRID, 1, 1, true).cells());
        assertThrows(IllegalArgumentException.class,
                () -> new LodSettings(48, LodRule.PAPER, 2, 100, LodMode.QUADTREE, 1, 1, true));
        assertThrows(IllegalArgumentException.class,
                () -> new LodSettings(65, LodRule.PAPER, 2, 0, LodMode.QUADTREE, 1, 1, true));
        assertThrows(IllegalArgumentException.class,
                () -> new LodSettings(65, LodRule.SCREEN_ERROR, 0, 100, LodMode.QUADTREE, 1, 1, true));
    }
}

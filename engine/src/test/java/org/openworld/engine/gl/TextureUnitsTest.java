package org.openworld.engine.gl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

class TextureUnitsTest {

    @Test
    void samplersGetTheUnitsFromZeroInTheOrderAdded() {
        TextureUnits units = new TextureUnits();
        assertEquals(new TextureUnits.Sampler("heights", 0), units.add("heights"));
        assertEquals(new TextureUnits.Sampler("gradients", 1), units.add("gradients"));
    }

    @Test
    void aSamplerAddedTwiceIsRefused() {
        TextureUnits units = new TextureUnits();
        units.add("scene");
        assertThrows(IllegalArgumentException.class, () -> units.add("scene"));
    }

    @Test
    void theSystemsUnitsNeverReachTheSharedOnes() {
        TextureUnits units = new TextureUnits();
        Set<Integer> shared = new HashSet<>();
        for (SharedTexture texture : SharedTexture.values()) {
            shared.add(texture.unit());
        }
        // every unit below the shared ones can be handed out, and not one more
        for (int i = 0; i < SharedTexture.lowestUnit(); i++) {
            assertTrue(!shared.contains(units.add("s" + i).unit()));
        }
        IllegalStateException full = assertThrows(IllegalStateException.class, () -> units.add("one-too-many"));
        assertTrue(full.getMessage().contains("one-too-many"), full.getMessage());
    }

    @Test
    void theSharedTexturesTakeTheTopOfTheSixteenGuaranteedUnits() {
        // OpenGL 3.3 guarantees 16 units to a fragment shader; the shared textures take its last ones, distinct
        Set<Integer> units = new HashSet<>();
        for (SharedTexture texture : SharedTexture.values()) {
            assertTrue(texture.unit() < 16 && units.add(texture.unit()), texture + " on unit " + texture.unit());
        }
        assertEquals(15, SharedTexture.values()[SharedTexture.values().length - 1].unit());
    }
}

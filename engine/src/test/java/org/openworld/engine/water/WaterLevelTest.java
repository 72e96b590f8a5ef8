package org.openworld.engine.water;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.openworld.engine.Engine;
import org.openworld.engine.core.World;
import org.openworld.engine.environment.WaterLevel;
import org.openworld.engine.settings.Settings;

/** The water publishes its plane as the world's {@link WaterLevel}, without GL: its update alone. */
class WaterLevelTest {

    private static final double STEP = 1.0 / 60;

    @Test
    void eachUpdatePublishesTheLevelOfTheSettingsAsTheyAreNow() {
        WaterSystem water = new WaterSystem();
        Settings settings = Engine.settingsFor(List.of(water));
        World world = new World();
        world.setResource(settings);
        settings.set("water.level", "12.5");
        water.update(world, STEP);
        assertEquals(12.5, world.resource(WaterLevel.class).height());
        // a change from the settings panel is seen at the next step
        settings.set("water.level", "-3");
        water.update(world, STEP);
        assertEquals(-3, world.resource(WaterLevel.class).height());
    }

    @Test
    void theLevelIsPublishedSoAnOpaqueReaderCanGoBeforeTheWater() {
        assertTrue(new WaterSystem().spec().published().contains(WaterLevel.class));
        assertFalse(new WaterSystem().spec().writes().contains(WaterLevel.class), "a written level would put every "
                + "reader after the water, and an opaque reader must draw before it: a cycle");
    }
}

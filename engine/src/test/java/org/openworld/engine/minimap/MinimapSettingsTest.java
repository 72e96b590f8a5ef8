package org.openworld.engine.minimap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.openworld.engine.Engine;
import org.openworld.engine.core.World;
import org.openworld.engine.environment.WaterLevel;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsException;

/** The minimap's keys, where its square goes, and the water level it takes. */
class MinimapSettingsTest {

    @Test
    void theSystemBringsItsKeysOffByDefault() {
        Settings settings = Engine.settingsFor(List.of(new MinimapSystem()));
        assertTrue(settings.keys().containsAll(List.of("system.minimap", "minimap.size", "minimap.range",
                "minimap.corner")));
        assertEquals("off", settings.text("system.minimap"));
        settings.set("minimap.corner", "bottom-left");
        assertEquals(MinimapSettings.Corner.BOTTOM_LEFT, settings.get(MinimapSettings.class).corner());
        assertThrows(SettingsException.class, () -> settings.set("minimap.range", "10"));
    }

    @Test
    void theSquareIsItsShareOfTheHeightInItsCornerClearOfTheEdges() {
        MinimapSettings s = MinimapSettings.DEFAULTS;
        int margin = (int) Math.round(MinimapSettings.MARGIN * 1080);
        int side = (int) Math.round(s.size() * 1080);
        assertEquals(new MinimapSettings.Square(1920 - margin - side, 1080 - margin - side, side),
                s.square(1920, 1080));
        assertEquals(new MinimapSettings.Square(1920 - margin - side, margin, side),
                withCorner(s, MinimapSettings.Corner.TOP_RIGHT).square(1920, 1080));
        assertEquals(new MinimapSettings.Square(margin, 1080 - margin - side, side),
                withCorner(s, MinimapSettings.Corner.BOTTOM_LEFT).square(1920, 1080));
        assertEquals(new MinimapSettings.Square(margin, margin, side),
                withCorner(s, MinimapSettings.Corner.TOP_LEFT).square(1920, 1080));
        // a tall, narrow picture: the square shrinks to fit its width
        MinimapSettings.Square narrow = new MinimapSettings(0.9, 4000, MinimapSettings.Corner.TOP_RIGHT)
                .square(300, 1000);
        assertEquals(300 - 2 * 20, narrow.side());
        assertEquals(20, narrow.left());
    }

    @Test
    void theWaterLevelIsTheWorldsOrNoneWithoutOne() {
        World world = new World();
        assertEquals(Double.NEGATIVE_INFINITY, MinimapSystem.waterLevel(world));
        world.setResource(new WaterLevel(35));
        assertEquals(35, MinimapSystem.waterLevel(world));
    }

    static MinimapSettings withCorner(MinimapSettings s, MinimapSettings.Corner corner) {
        return new MinimapSettings(s.size(), s.range(), corner);
    }
}

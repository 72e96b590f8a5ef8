package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.joml.Vector2d;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsException;

/** The cloud settings' keys, their checks, and the uniforms they pack. */
class CloudSettingsTest {

    /** Cloud settings from the defaults with {@code key=value} assignments applied, as {@code --set} does. */
    static CloudSettings settings(String... assignments) {
        Settings settings = new Settings(List.of(CloudSettings.SETTINGS));
        for (String a : assignments) {
            settings.apply(a);
        }
        return settings.get(CloudSettings.class);
    }

    @Test
    void defaultsAreValidAndKeysAreKebabCase() {
        assertEquals(CloudSettings.DEFAULTS, settings());
        assertEquals(CloudSettings.Mapping.SPHERICAL, settings("clouds.mapping=SPHERICAL").mapping());
        assertEquals(0.8, settings("clouds.cover=0.8").cover());
        assertEquals(5000, settings("clouds.tile-size=5000").tileSize());
        assertEquals(2, settings("clouds.horizon-fog=2").horizonFog());
        assertEquals(90, settings("clouds.wind-direction=90").windDirection());
    }

    @Test
    void sampleCountsMustBePowersOfTwo() {
        var e = assertThrows(SettingsException.class, () -> settings("clouds.resolution=100"));
        assertTrue(e.getMessage().contains("clouds.resolution") && e.getMessage().contains("power of two"),
                e.getMessage());
        e = assertThrows(SettingsException.class, () -> settings("clouds.frames=12"));
        assertTrue(e.getMessage().contains("clouds.frames"), e.getMessage());
        assertEquals(64, settings("clouds.resolution=64").resolution());
    }

    @Test
    void rangesAreChecked() {
        assertThrows(SettingsException.class, () -> settings("clouds.cover=1.5"));
        assertThrows(SettingsException.class, () -> settings("clouds.altitude=100"));
        assertThrows(SettingsException.class, () -> settings("clouds.mapping=CUBIC"));
    }

    @Test
    void windBlowsTowardsItsDirectionAndWrapsByTheTile() {
        // 10 m/s towards the east (90 deg) for 100 s: 1000 m along +x, nothing along z
        CloudSettings east = settings("clouds.wind-speed=10", "clouds.wind-direction=90", "clouds.tile-size=5000");
        Vector2d d = east.windOffset(100, new Vector2d());
        assertEquals(1000, d.x, 1e-6);
        assertEquals(0, d.y, 1e-6);
        Vector3f velocity = east.windVelocity(new Vector3f());
        assertEquals(10, velocity.x, 1e-5, "the Wind resource the snow drifts in");
        assertEquals(0, velocity.z, 1e-5);
        assertEquals(0, velocity.y, 0);
        // after 700 s it has gone 7000 m, 2000 m into the second tile
        assertEquals(2000, east.windOffset(700, new Vector2d()).x, 1e-6);

        // towards the north: along −z, wrapped into [0, tile)
        CloudSettings north = settings("clouds.wind-speed=10", "clouds.wind-direction=0", "clouds.tile-size=5000");
        Vector2d n = north.windOffset(100, new Vector2d());
        assertEquals(0, n.x, 1e-6);
        assertEquals(4000, n.y, 1e-6);
        assertEquals(-10, north.windVelocity(new Vector3f()).z, 1e-5, "north is -z");
    }

    @Test
    void uniformsCarryThresholdGeometryPhaseAndMode() {
        CloudSettings s = settings("clouds.mapping=spherical-fog", "clouds.period=200", "clouds.altitude=3000",
                "clouds.tile-size=10000", "clouds.horizon-fog=0.5");
        Vector4f params = s.cloudParams(0.25f, new Vector4f());
        assertEquals(new Vector4f(0.25f, 3000, 10000, 5000), params);

        Vector4f motion = s.cloudMotion(450, new Vector4f());
        assertEquals(0.25, motion.z, 1e-6, "450 s is a quarter into the third 200 s loop");
        assertEquals(1, motion.w, "SPHERICAL_FOG is mode 1");
        assertTrue(motion.x >= 0 && motion.x < 10000 && motion.y >= 0 && motion.y < 10000);
    }
}

package org.openworld.engine.terrain;

import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Views that show how the terrain is built rather than how it looks.
 *
 * @param wireframe draw the triangles' edges only: the stitching between levels becomes visible
 * @param colouring what the surface colour shows: shaded, the LOD level (figure 6) or the tangent frame (figure 4)
 * @param freezeLod keep choosing levels from where the camera was when this was switched on, so flying away shows the
 *                  cut from outside (with {@code culling.freeze}, the frozen frustum too)
 */
public record TerrainDebugSettings(
        @Setting(doc = "draw triangle edges only") boolean wireframe,
        @Setting(doc = "surface colour: shaded, by LOD level (figure 6) or the tangent frame (figure 4)")
        Colouring colouring,
        @Setting(doc = "choose levels from where the camera was when switched on") boolean freezeLod) {

    /** What the terrain's surface colour shows. */
    public enum Colouring {
        /** Materials, light and fog: the normal view. */
        SHADED,
        /** One colour per geomipmap level, lit: the quadtree cut (figure 6). */
        LEVELS,
        /** The local tangent frame as colour (figure 4). */
        TANGENT_SPACE
    }

    public static final TerrainDebugSettings DEFAULTS = new TerrainDebugSettings(false, Colouring.SHADED, false);

    public static final SettingsGroup<TerrainDebugSettings> SETTINGS =
            SettingsGroup.of("terrain-debug", TerrainDebugSettings.class, DEFAULTS);
}

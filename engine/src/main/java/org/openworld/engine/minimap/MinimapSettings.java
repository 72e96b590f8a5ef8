package org.openworld.engine.minimap;

import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Settings of the minimap, keys {@code minimap.*}.
 *
 * @param size    the map's side as a share of the picture's height
 * @param range   the ground shown across the map, west edge to east edge (and north to south), metres
 * @param corner  the corner of the picture the map sits in
 */
public record MinimapSettings(
        @Setting(doc = "side of the map as a share of the picture height", min = 0.05, max = 0.9) double size,
        @Setting(doc = "ground shown across the map", unit = "m", min = 100, max = 100_000) double range,
        @Setting(doc = "corner of the picture the map sits in") Corner corner) {

    /** Where in the picture the map sits. */
    public enum Corner { TOP_LEFT, TOP_RIGHT, BOTTOM_LEFT, BOTTOM_RIGHT }

    public static final MinimapSettings DEFAULTS = new MinimapSettings(
            0.3,              // 324 px at 1080p: readable, and leaves most of the view free
            4000,             // m: as wide as the default world's tile, a few hills and lakes each way
            Corner.BOTTOM_RIGHT); // clear of the window's settings panel (top left) and HUD (top right)

    public static final SettingsGroup<MinimapSettings> SETTINGS =
            SettingsGroup.of("minimap", MinimapSettings.class, DEFAULTS);

    /** Gap between the map and the picture's edges, as a share of the picture's height (22 px at 1080p). */
    static final double MARGIN = 0.02;

    public MinimapSettings {
        if (corner == null) {
            throw new IllegalArgumentException("the minimap corner must be given");
        }
    }

    /**
     * The map's square in a picture, in picture pixels.
     *
     * @param left pixels from the picture's left edge to the map's
     * @param top  pixels from the picture's top edge to the map's (rows counted downwards, as in an image)
     * @param side the square's side, pixels
     */
    public record Square(int left, int top, int side) {

        /** Whether the pixel at column x, row y (0 the top row) lies on the map. */
        public boolean contains(int x, int y) {
            return x >= left && x < left + side && y >= top && y < top + side;
        }
    }

    /** Where the map goes in a picture of this size: {@link #size} of its height, {@link #MARGIN} from the corner. */
    public Square square(int width, int height) {
        int margin = (int) Math.round(MARGIN * height);
        int side = (int) Math.min(Math.round(size * height), Math.min(width, height) - 2L * margin);
        boolean left = corner == Corner.TOP_LEFT || corner == Corner.BOTTOM_LEFT;
        boolean top = corner == Corner.TOP_LEFT || corner == Corner.TOP_RIGHT;
        return new Square(left ? margin : width - margin - side, top ? margin : height - margin - side, side);
    }
}

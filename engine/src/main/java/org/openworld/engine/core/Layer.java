package org.openworld.engine.core;

/**
 * Where a system's drawing lies in each pass it draws in, in the order the layers are drawn
 * ({@link SystemSpec#layer}). A system of a later layer follows every system of an earlier layer that draws in one of
 * its passes, without naming them, so a new system of an earlier layer goes before it whatever it is called
 * ({@link SystemOrder}); within a layer the declared reads, writes and {@link SystemSpec#after} order the systems.
 */
public enum Layer {

    /** The surfaces (terrain, trees): they write depth; the default. */
    OPAQUE,

    /**
     * What lies behind every surface (the sky). It has no order of its own: its update keeps its place in the frame
     * order, so an opaque system may read what it writes (the sun), while in each pass it draws right after the last
     * opaque system ({@link SystemOrder#drawOrder}). It draws at the far plane with the depth test on and depth
     * writes off, so the pixels an opaque surface already covers fail the depth test before they are shaded (early
     * depth rejection) and each pixel is shaded once. Work the opaque systems need from it (tables, maps) it does
     * before the passes, in its update.
     */
    BACKGROUND,

    /**
     * Drawn over the finished opaque picture, which it reads (the water copies the scene's colour and depth to show
     * what lies behind and under it): it follows the opaque systems and the background of its passes.
     */
    OVER_OPAQUE,

    /** Blended over everything else of its passes (particles, the minimap): it stays last whichever systems a scene has. */
    TRANSPARENT;

    /** Whether this layer is ordered after the systems of every earlier layer by an edge of the frame order. */
    boolean followsEarlierLayers() {
        return this == OVER_OPAQUE || this == TRANSPARENT;
    }
}

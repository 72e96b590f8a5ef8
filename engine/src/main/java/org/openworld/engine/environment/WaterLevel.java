package org.openworld.engine.environment;

/**
 * The height of the water plane, metres (0 is sea level): published by the system that draws the water (from
 * {@code water.level}, at init and renewed every update; published, not written, so it orders no reader after the
 * water, which draws over the opaque systems that read it), read by whatever must know where the water is (the minimap draws
 * the ground below it blue; what grows on the ground stops at the shore). A world without one has no water. With the
 * water system switched off the level stays as last written: the water is not drawn, but the lake is still part of
 * the world, as the terrain's height field is.
 *
 * @param height metres above sea level
 */
public record WaterLevel(double height) {

    public WaterLevel {
        if (!Double.isFinite(height)) {
            throw new IllegalArgumentException("water level " + height + " is not a number of metres");
        }
    }
}

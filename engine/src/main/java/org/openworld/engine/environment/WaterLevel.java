package org.openworld.engine.environment;

/**
 * The height of the water plane, metres (0 is sea level): written by the system that draws the water, read by
 * whatever must know where the water is (the minimap's blue, the snow that melts into it, the terrain's shore). A
 * world without one has no water.
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

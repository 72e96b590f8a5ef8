package org.openworld.engine.core;

/**
 * The ground's height under any horizontal position, as a world resource. The terrain provides the real one; walk
 * mode and ground-relative camera paths read whichever the world has.
 */
@FunctionalInterface
public interface HeightField {

    /** A flat world at sea level. */
    HeightField FLAT = (x, z) -> 0;

    /**
     * @param x east, metres
     * @param z south, metres
     * @return ground height above sea level at (x, z), metres
     */
    double heightAt(double x, double z);
}

package org.openworld.engine.environment;

/**
 * How wet the ground is, anywhere: 0 dry rock or a sun-baked ridge, 1 a valley floor where water gathers. A world
 * resource published by whatever models the water's flow over the land; the plants read it to choose where forests
 * grow. A world without one leaves each reader to its own stand-in (the vegetation's is named in its package).
 */
@FunctionalInterface
public interface Moisture {

    /**
     * @param x east, metres
     * @param z south, metres
     * @return wetness at (x, z), 0 to 1
     */
    double at(double x, double z);
}

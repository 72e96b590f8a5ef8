package org.openworld.engine.shadow;

import org.openworld.engine.core.Cullable;
import org.openworld.engine.core.World;

/**
 * The lowest and highest point of everything the culling system knows of (the roots of the bounds trees): what can
 * cast a shadow lies between. A light box reaches towards the sun until its ray climbs over {@link #high}, and the
 * probe's ray march stops there.
 *
 * @param low  metres; +∞ when the world has nothing to cull
 * @param high metres; −∞ when the world has nothing to cull
 */
record CasterHeights(double low, double high) {

    static CasterHeights of(World world) {
        double[] range = {Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY};
        world.each(Cullable.class, (entity, cullable) -> {
            float[] root = cullable.tree().boxes();
            range[0] = Math.min(range[0], root[1]);
            range[1] = Math.max(range[1], root[4]);
        });
        return new CasterHeights(range[0], range[1]);
    }

    /** Metres from the lowest to the highest, 0 for an empty world. */
    double span() {
        return high > low ? high - low : 0;
    }
}

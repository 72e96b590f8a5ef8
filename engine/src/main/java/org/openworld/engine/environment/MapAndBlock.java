package org.openworld.engine.environment;

import org.openworld.engine.gl.GlTexture;
import org.openworld.engine.gl.GpuBuffer;
import org.openworld.engine.gl.Labelled;

/**
 * A shared map with the uniform block that says how to read it (the sun's and the clouds' shadows, the forests'
 * cover): labelled and closed as one.
 */
public interface MapAndBlock extends Labelled {

    /** The map. */
    GlTexture map();

    /** The block that says how to read it. */
    GpuBuffer block();

    /** Names the map {@code name.map} and the block {@code name.block}. */
    @Override
    default void label(String name) {
        map().label(name + ".map");
        block().label(name + ".block");
    }

    @Override
    default void close() {
        map().close();
        block().close();
    }
}

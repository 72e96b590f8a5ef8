package org.openworld.engine.environment;

import org.joml.Vector3f;
import org.joml.Vector3fc;

/**
 * The wind on the cloud layer: a horizontal velocity, world space, m/s. Written by the system that moves the clouds,
 * so whatever drifts in the air (the snow) goes the way the sky does; a world without one is calm.
 *
 * @param velocity metres per second, x east, z south, y 0
 */
public record Wind(Vector3fc velocity) {

    /** Still air. */
    public static final Wind CALM = new Wind(new Vector3f());

    public Wind {
        velocity = new Vector3f(velocity);
    }
}

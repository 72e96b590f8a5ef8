package org.openworld.engine.camera;

/**
 * Where a camera is and where it looks, in the conventions of docs/design.md: metres, Y up, X east, Z south.
 *
 * @param x     east, metres
 * @param y     height above sea level, metres
 * @param z     south, metres
 * @param yaw   degrees clockwise from north seen from above (0 north, 90 east, 180 south, 270 west)
 * @param pitch degrees, positive looking up, within [-89, 89]
 * @param fov   vertical field of view, degrees
 */
public record CameraPose(double x, double y, double z, double yaw, double pitch, double fov) {

    /** The field of view used when a pose does not give one, degrees. */
    public static final double DEFAULT_FOV = 60;
}

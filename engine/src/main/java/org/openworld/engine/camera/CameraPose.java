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

    /**
     * The farthest a camera may be from the origin along each axis, metres: 2^24 m, 16 777 km. The GPU sees only
     * positions from the render origin (org.openworld.engine.origin), so its floats break nowhere; what ends the
     * world is the CPU's float copies of world positions (the level of detail's eye, the culling's boxes, the light
     * boxes' fit), whose 24 bits are 1 m apart from 2^24 m on: beyond it a patch's level or a shadow's box could be
     * metres off. Every other limit lies farther: the render origin counted in float steps (2^24 tiles), the
     * unbounded world's int sample indices (2^31 samples). {@code --camera} and camera path files refuse a coordinate
     * beyond it.
     */
    public static final double MAX_COORDINATE_M = 1 << 24;

    /** Whether a coordinate lies within {@link #MAX_COORDINATE_M} of the origin. */
    public static boolean drawable(double metres) {
        return Math.abs(metres) <= MAX_COORDINATE_M;
    }

    /** The field of view used when a pose does not give one, degrees. */
    public static final double DEFAULT_FOV = 60;
}

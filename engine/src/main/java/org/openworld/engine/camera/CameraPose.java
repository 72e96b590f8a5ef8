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
     * The farthest a camera may be from the origin along each axis, metres: 1000 km. The world's heights are doubles,
     * but the GPU takes positions as float32, whose 24 bits resolve 6 cm at 1000 km and 25 cm at 4000 km: measured
     * ({@code openworld shot --camera D,400,D,45,-10}), the picture at 1000 km is whole and at 4000 km the ground
     * shows holes and the snow specks of sky. {@code --camera} and camera path files refuse a coordinate beyond it.
     */
    public static final double MAX_COORDINATE_M = 1_000_000;

    /** Whether a coordinate lies within {@link #MAX_COORDINATE_M} of the origin. */
    public static boolean drawable(double metres) {
        return Math.abs(metres) <= MAX_COORDINATE_M;
    }

    /** The field of view used when a pose does not give one, degrees. */
    public static final double DEFAULT_FOV = 60;
}

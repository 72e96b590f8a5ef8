package org.openworld.engine.camera;

/**
 * One key of a camera path: a time and the pose the camera has then. The limits here are the ones the path file
 * format checks.
 *
 * @param time  seconds on the path's clock
 * @param x     east, metres
 * @param y     metres above sea level, or above the ground when the path's heights are {@link HeightReference#GROUND}
 * @param z     south, metres
 * @param yaw   degrees clockwise from north; any finite value, the path takes the shorter turn between keys
 * @param pitch degrees, positive looking up, within [-{@link #MAX_PITCH}, {@link #MAX_PITCH}]
 * @param fov   vertical field of view, degrees, strictly between {@link #MIN_FOV} and {@link #MAX_FOV}
 */
public record Keyframe(double time, double x, double y, double z, double yaw, double pitch, double fov) {

    /** Steepest pitch, degrees: at ±90 the view direction is vertical and yaw no longer defines the camera's up. */
    public static final double MAX_PITCH = 89;

    /** Field of view bounds, degrees, both excluded: a projection needs 0 &lt; fov &lt; 180. */
    public static final double MIN_FOV = 1;
    public static final double MAX_FOV = 179;

    public Keyframe {
        for (double v : new double[] {time, x, y, z, yaw, pitch, fov}) {
            if (!Double.isFinite(v)) {
                throw new IllegalArgumentException("keyframe values must be finite: " + v);
            }
        }
        if (Math.abs(pitch) > MAX_PITCH) {
            throw new IllegalArgumentException("pitch must be within [-89, 89] degrees: " + pitch);
        }
        if (!(fov > MIN_FOV && fov < MAX_FOV)) {
            throw new IllegalArgumentException("fov must be within (1, 179) degrees: " + fov);
        }
    }

    /** The key at {@code time} for a pose; its y stays above sea level. */
    public static Keyframe of(double time, CameraPose pose) {
        return new Keyframe(time, pose.x(), pose.y(), pose.z(), pose.yaw(), pose.pitch(), pose.fov());
    }
}

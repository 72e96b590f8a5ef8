package org.openworld.engine.camera;

import java.util.Arrays;
import java.util.List;
import java.util.Objects;
import java.util.function.ToDoubleFunction;

import org.joml.Vector3d;
import org.openworld.engine.core.HeightField;

/**
 * A scripted camera flight: keyframes at increasing times, and the smooth motion through them.
 *
 * <p>Position follows a centripetal Catmull–Rom curve through the keyframe positions ({@link CatmullRom}). The
 * segment is chosen by time, and the local parameter u = (t - t_i) / (t_{i+1} - t_i) is mapped onto the segment's
 * centripetal knot interval, so the camera reaches every key exactly at its time. The position is continuous; its
 * speed may step at a key where the neighbouring segments map different knot intervals onto their durations. At
 * either end a phantom point P_-1 = 2 P_0 - P_1 (and P_n = 2 P_{n-1} - P_{n-2}) continues the path straight on.
 *
 * <p>Yaw is first unwrapped so that each key differs from the previous one by at most 180°: 350° then 10° becomes
 * 350° then 370°, and the camera turns 20° through north instead of 340° back through south. Yaw, pitch and field
 * of view then follow a monotone cubic over time ({@link MonotoneCubic}): continuous and smooth, and never past a
 * key's value, so the camera does not swing past a key and pitch stays within its limits. The sampled yaw is
 * normalised to [0, 360).
 */
public final class CameraPath {

    private final HeightReference heights;
    private final List<Keyframe> keys;
    private final double[] time;
    private final double[] x;
    private final double[] y;
    private final double[] z;
    private final double[] yaw;
    private final double[] pitch;
    private final double[] fov;

    /**
     * @param heights what the keys' y is measured from
     * @param keys    at least two, with strictly increasing times
     * @throws IllegalArgumentException for fewer than two keys or times that do not increase
     */
    public CameraPath(HeightReference heights, List<Keyframe> keys) {
        this.heights = Objects.requireNonNull(heights, "heights");
        this.keys = List.copyOf(keys);
        if (this.keys.size() < 2) {
            throw new IllegalArgumentException("a camera path needs at least 2 keyframes, got " + this.keys.size());
        }
        for (int i = 1; i < this.keys.size(); i++) {
            if (this.keys.get(i).time() <= this.keys.get(i - 1).time()) {
                throw new IllegalArgumentException("keyframe times must increase: " + this.keys.get(i - 1).time()
                        + " then " + this.keys.get(i).time());
            }
        }
        time = channel(Keyframe::time);
        x = channel(Keyframe::x);
        y = channel(Keyframe::y);
        z = channel(Keyframe::z);
        yaw = unwrap(channel(Keyframe::yaw));
        pitch = channel(Keyframe::pitch);
        fov = channel(Keyframe::fov);
    }

    public HeightReference heights() {
        return heights;
    }

    public List<Keyframe> keys() {
        return keys;
    }

    /** Time of the first key, seconds. */
    public double startTime() {
        return time[0];
    }

    /** Time of the last key, seconds. */
    public double endTime() {
        return time[time.length - 1];
    }

    /** Seconds from the first key to the last. */
    public double duration() {
        return endTime() - startTime();
    }

    /**
     * The camera at a time on the path's clock. Times before the first key give the first key, times after the last
     * give the last.
     *
     * @param seconds time on the path's clock (the file's time column)
     * @param ground  the terrain; read only when {@link #heights()} is {@link HeightReference#GROUND}, where the
     *                sampled y is {@code ground.heightAt(x, z)} plus the interpolated eye height
     * @return the pose, y above sea level, yaw in [0, 360)
     */
    public CameraPose sample(double seconds, HeightField ground) {
        double t = Math.max(startTime(), Math.min(endTime(), seconds));
        int i = segmentAt(t);
        double u = (t - time[i]) / (time[i + 1] - time[i]);
        Vector3d p = CatmullRom.centripetal(point(i - 1), point(i), point(i + 1), point(i + 2), u, new Vector3d());
        double seaY = heights == HeightReference.GROUND ? ground.heightAt(p.x, p.z) + p.y : p.y;
        return new CameraPose(p.x, seaY, p.z, normalizeDegrees(MonotoneCubic.interpolate(time, yaw, i, t)),
                MonotoneCubic.interpolate(time, pitch, i, t), MonotoneCubic.interpolate(time, fov, i, t));
    }

    /** Index i of the segment [t_i, t_{i+1}] holding t, for t within the path's times. */
    private int segmentAt(double t) {
        int found = Arrays.binarySearch(time, t);
        int i = found >= 0 ? found : -found - 2;
        return Math.max(0, Math.min(time.length - 2, i));
    }

    private Vector3d point(int i) {
        return new Vector3d(extended(x, i), extended(y, i), extended(z, i));
    }

    /** values[i], continued past either end by reflection: p_-1 = 2 p_0 - p_1, p_n = 2 p_{n-1} - p_{n-2}. */
    private static double extended(double[] values, int i) {
        int n = values.length;
        if (i < 0) {
            return 2 * values[0] - values[1];
        }
        if (i >= n) {
            return 2 * values[n - 1] - values[n - 2];
        }
        return values[i];
    }

    private double[] channel(ToDoubleFunction<Keyframe> field) {
        return keys.stream().mapToDouble(field).toArray();
    }

    /** Yaws rewritten so each differs from the previous by the shorter turn, in (-180, 180] degrees. */
    private static double[] unwrap(double[] yaws) {
        double[] unwrapped = yaws.clone();
        for (int i = 1; i < yaws.length; i++) {
            double turn = (yaws[i] - yaws[i - 1]) % 360;
            if (turn > 180) {
                turn -= 360;
            } else if (turn <= -180) {
                turn += 360;
            }
            unwrapped[i] = unwrapped[i - 1] + turn;
        }
        return unwrapped;
    }

    /** The same direction in [0, 360) degrees. */
    private static double normalizeDegrees(double degrees) {
        double wrapped = degrees % 360;
        if (wrapped < 0) {
            wrapped += 360;
        }
        return wrapped < 360 ? wrapped : 0; // -1e-17 + 360 rounds to 360
    }
}

package org.openworld.engine.camera;

import org.openworld.engine.settings.Setting;

/**
 * Settings of the camera controller ({@link CameraSystem}), keys {@code camera.*}. The motion model these feed is
 * written out in {@link CameraSystem}'s class comment.
 *
 * @param fov              vertical field of view written into the pose (a replayed path may give its own)
 * @param flySpeed         terminal speed in fly mode: the speed reached when a move key is held long enough
 * @param boost            factor on the fly speed while Shift is held
 * @param acceleration     rate at which the velocity approaches the wished velocity while a move key is held
 *                         (fly) or at any time (walk); 1 / rate is the time constant, e.g. 4/s reaches 63 % of the
 *                         speed in 0.25 s and 98 % in 1 s
 * @param damping          rate at which the fly velocity dies away once the move keys are released: the speed
 *                         falls by a factor e every 1 / damping seconds, so the camera glides to a halt
 * @param mouseSensitivity turn per pixel of mouse movement
 * @param lookSmoothing    time constant of the exponential approach of the view to the mouse's aim; 0 turns at once
 * @param turnSpeed        turn rate of the arrow keys, for keyboard-only users
 * @param walkSpeed        walking speed
 * @param runFactor        factor on the walking speed while Shift is held (running)
 * @param eyeHeight        eye height above the ground in walk mode
 * @param stepSmoothing    time constant with which the eye follows the ground in walk mode, so steps in the ground
 *                         do not jolt the view; 0 follows at once
 * @param mode             the mode at start (key V toggles it)
 */
public record CameraSettings(
        @Setting(doc = "vertical field of view", unit = "deg", min = 20, max = 120) double fov,
        @Setting(doc = "fly speed (terminal speed with a move key held)", unit = "m/s", min = 0.1, max = 5000)
        double flySpeed,
        @Setting(doc = "fly speed factor while Shift is held", min = 1, max = 100) double boost,
        @Setting(doc = "rate of approach to the wished velocity", unit = "1/s", min = 0.1, max = 100)
        double acceleration,
        @Setting(doc = "fly velocity decay rate after the keys are released", unit = "1/s", min = 0, max = 100)
        double damping,
        @Setting(doc = "mouse look: turn per pixel", unit = "deg/px", min = 0.001, max = 2) double mouseSensitivity,
        @Setting(doc = "mouse look smoothing time constant (0 = none)", unit = "s", min = 0, max = 1)
        double lookSmoothing,
        @Setting(doc = "arrow keys turn rate", unit = "deg/s", min = 1, max = 720) double turnSpeed,
        @Setting(doc = "walking speed", unit = "m/s", min = 0.1, max = 20) double walkSpeed,
        @Setting(doc = "walking speed factor while Shift is held (running)", min = 1, max = 10) double runFactor,
        @Setting(doc = "eye height above the ground when walking", unit = "m", min = 0.5, max = 10) double eyeHeight,
        @Setting(doc = "walk: time constant of the eye following the ground (0 = none)", unit = "s", min = 0, max = 1)
        double stepSmoothing,
        @Setting(doc = "movement mode at start; key V toggles") CameraMode mode) {

    public static final CameraSettings DEFAULTS = new CameraSettings(
            60,     // deg: a natural vertical view on a desktop screen
            40,     // m/s: 144 km/h, crosses a 10 km world in about four minutes
            8,      // Shift: 320 m/s for long hops
            4,      // 1/s: 98 % of the speed after one second
            2,      // 1/s: the glide loses 86 % of its speed in one second
            0.12,   // deg/px: a 1500 px sweep turns half a circle
            0.05,   // s: takes the edge off mouse jitter without a felt lag
            90,     // deg/s: a quarter turn per second
            1.6,    // m/s: an unhurried walking pace
            3,      // 4.8 m/s: a jog
            1.7,    // m: eye level of a standing adult
            0.12,   // s: a step up settles within a third of a second
            CameraMode.FLY);
}

package org.openworld.engine.camera;

import org.joml.Vector3d;

/**
 * Directions and angles in docs/design.md's conventions, written once for every class that turns a yaw and a pitch into
 * a vector (the camera controller, camera paths, the water's mirror camera…).
 *
 * <p>Metres, Y up, X east, Z south (north is −Z). Yaw is in degrees clockwise from north seen from above
 * (0 north, 90 east, 180 south, 270 west); pitch is in degrees, positive looking up. The view direction is
 * <pre>
 *   forward(yaw, pitch) = ( sin yaw · cos pitch,  sin pitch,  −cos yaw · cos pitch )
 *   right(yaw)          = ( cos yaw,  0,  sin yaw )          = forward × up, always horizontal
 * </pre>
 * the same orientation as {@code ViewCamera.perspective}'s view matrix {@code Rx(−pitch) · Ry(yaw) · T(−eye)},
 * which maps {@code forward} onto the view space's −Z.
 */
public final class CameraMath {

    /** Steepest pitch the camera takes, degrees: at ±90 the yaw would be undefined (gimbal lock). */
    public static final double MAX_PITCH = 89;

    private CameraMath() {
    }

    /** Unit view direction for a yaw and pitch in degrees. */
    public static Vector3d forward(double yawDeg, double pitchDeg) {
        double yaw = Math.toRadians(yawDeg);
        double pitch = Math.toRadians(pitchDeg);
        return new Vector3d(Math.sin(yaw) * Math.cos(pitch), Math.sin(pitch), -Math.cos(yaw) * Math.cos(pitch));
    }

    /** Unit horizontal direction the yaw faces (the forward vector at pitch 0): where walking goes. */
    public static Vector3d flatForward(double yawDeg) {
        return forward(yawDeg, 0);
    }

    /** Unit horizontal direction to the viewer's right, {@code forward × up}: where strafing goes. */
    public static Vector3d right(double yawDeg) {
        double yaw = Math.toRadians(yawDeg);
        return new Vector3d(Math.cos(yaw), 0, Math.sin(yaw));
    }

    /** Yaw, degrees in [0, 360), of a direction (its horizontal part); 0 for a vertical direction. */
    public static double yawOf(double dx, double dz) {
        return dx == 0 && dz == 0 ? 0 : normalizeYaw(Math.toDegrees(Math.atan2(dx, -dz)));
    }

    /** Pitch, degrees in [−90, 90], of a direction that need not be of unit length. */
    public static double pitchOf(double dx, double dy, double dz) {
        return Math.toDegrees(Math.atan2(dy, Math.hypot(dx, dz)));
    }

    /** The same yaw in [0, 360). */
    public static double normalizeYaw(double yawDeg) {
        double y = yawDeg % 360;
        if (y < 0) {
            y += 360;
        }
        // −1e-15 % 360 + 360 rounds to exactly 360.
        return y >= 360 ? 0 : y;
    }

    /** The signed shortest turn from {@code fromDeg} to {@code toDeg}, degrees in [−180, 180). */
    public static double yawDifference(double fromDeg, double toDeg) {
        return normalizeYaw(toDeg - fromDeg + 180) - 180;
    }

    /** The pitch limited to [−{@value #MAX_PITCH}, {@value #MAX_PITCH}] degrees. */
    public static double clampPitch(double pitchDeg) {
        return Math.max(-MAX_PITCH, Math.min(MAX_PITCH, pitchDeg));
    }

    /**
     * The factor {@code e^(−rate·dt)} by which the gap to a target shrinks over {@code dt} seconds when a quantity
     * approaches it exponentially: the exact solution of {@code dq/dt = rate · (target − q)}, so the result does not
     * depend on how {@code dt} is cut into steps. A rate of 0 keeps the gap; an infinite rate closes it at once.
     *
     * @param rate per second (the inverse of a time constant)
     * @param dt   seconds
     */
    public static double decay(double rate, double dt) {
        return Math.exp(-rate * dt);
    }

    /**
     * {@link #decay} expressed with a time constant τ = 1 / rate, seconds; τ ≤ 0 means no smoothing (factor 0).
     */
    public static double decayWithTimeConstant(double tau, double dt) {
        return tau <= 0 ? 0 : Math.exp(-dt / tau);
    }
}

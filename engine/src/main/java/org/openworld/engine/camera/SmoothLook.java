package org.openworld.engine.camera;

/**
 * Smoothed turning: the mouse and the arrow keys move an aim (a target yaw and pitch), and the view follows the
 * aim by exponential approach, {@code angle ← aim + (angle − aim) · e^(−dt/τ)}, the yaw along the shorter way
 * round. The pitch aim is clamped to ±{@value CameraMath#MAX_PITCH}°, the yaw is kept in [0, 360); there is no roll.
 */
public final class SmoothLook {

    private double aimYaw;
    private double aimPitch;

    /** Points the aim at a view direction, e.g. the pose's when it was set from outside, so nothing swings back. */
    public void aimAt(double yawDeg, double pitchDeg) {
        aimYaw = CameraMath.normalizeYaw(yawDeg);
        aimPitch = CameraMath.clampPitch(pitchDeg);
    }

    /** Moves the aim by a turn, degrees: positive yaw turns right (clockwise from above), positive pitch looks up. */
    public void turn(double yawDeg, double pitchDeg) {
        aimAt(aimYaw + yawDeg, aimPitch + pitchDeg);
    }

    public double aimYaw() {
        return aimYaw;
    }

    public double aimPitch() {
        return aimPitch;
    }

    /**
     * The view after {@code dt} seconds of following the aim from ({@code yawDeg}, {@code pitchDeg}).
     *
     * @param tau time constant, seconds; 0 jumps to the aim
     * @return {yaw in [0, 360), pitch in [−89, 89]}, degrees
     */
    public double[] follow(double yawDeg, double pitchDeg, double dt, double tau) {
        double keep = CameraMath.decayWithTimeConstant(tau, dt);
        double yaw = aimYaw - CameraMath.yawDifference(yawDeg, aimYaw) * keep;
        double pitch = aimPitch + (CameraMath.clampPitch(pitchDeg) - aimPitch) * keep;
        return new double[] {CameraMath.normalizeYaw(yaw), CameraMath.clampPitch(pitch)};
    }
}

package org.openworld.engine.camera;

import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * A velocity with inertia: over each step it approaches a wished velocity {@code u} exponentially at a rate
 * {@code r}, the linear ODE {@code dv/dt = r · (u − v)}. Both the velocity and the distance covered are taken from
 * the ODE's exact solution for a {@code u} held over the step,
 * <pre>
 *   v(t + dt) = u + (v − u) · e^(−r·dt)
 *   x(t + dt) = x + u·dt + (v − u) · (1 − e^(−r·dt)) / r
 * </pre>
 * so two steps of dt/2 land exactly where one step of dt does: the motion does not depend on the frame rate.
 * With {@code u = 0} this is pure damping, {@code v ← v · e^(−r·dt)}, a glide to a halt.
 */
public final class InertialMotion {

    private final Vector3d velocity = new Vector3d();

    /** Current velocity, m/s (a read-only view). */
    public Vector3dc velocity() {
        return velocity;
    }

    /** Speed, m/s. */
    public double speed() {
        return velocity.length();
    }

    /** Zeroes the velocity. */
    public void stop() {
        velocity.zero();
    }

    /** Drops the vertical component (walking has none; landing ends a climb or a dive). */
    public void stopVertical() {
        velocity.y = 0;
    }

    /**
     * Advances the velocity by one step towards {@code wished}.
     *
     * @param wished the velocity approached, m/s
     * @param rate   r, per second; 0 keeps the velocity as it is
     * @param dt     the step, seconds
     * @return the displacement over the step, metres
     */
    public Vector3d step(Vector3dc wished, double rate, double dt) {
        double keep = CameraMath.decay(rate, dt);
        // (1 − e^(−r·dt)) / r, written with expm1 so it stays accurate for small r·dt and tends to dt as r → 0.
        double reach = rate * dt < 1e-12 ? dt : -Math.expm1(-rate * dt) / rate;
        Vector3d gap = new Vector3d(velocity).sub(wished);
        Vector3d displacement = new Vector3d(wished).mul(dt).fma(reach, gap);
        velocity.set(wished).fma(keep, gap);
        return displacement;
    }
}

package org.openworld.engine.camera;

import org.joml.Vector3d;
import org.joml.Vector3dc;
import org.openworld.engine.core.HeightField;

/**
 * The user's controls (paper section 1, "a realistic camera"): free flight with inertia, or walking on the
 * terrain, steered by keyboard and mouse. The director ({@link CameraSystem}) runs it under
 * {@link CameraDirection.Controls}: one {@link #step} per fixed update, from the camera's pose to the next.
 *
 * <h2>Motion model</h2>
 * Conventions of docs/design.md: metres, Y up, X east, Z south; yaw clockwise from north, pitch positive up. Each
 * update of length {@code dt} takes the camera's current pose as its starting point and does, in order:
 * <ol>
 *   <li><b>Look.</b> The mouse (only while looking) and the arrow keys move an aim:
 *       {@code aimYaw += dx · sensitivity + turnRight · turnSpeed · dt},
 *       {@code aimPitch −= dy · sensitivity − turnUp · turnSpeed · dt}, the pitch aim clamped to ±89°, the yaw
 *       kept in [0, 360). The view follows the aim by exponential approach with time constant τ
 *       ({@code camera.look-smoothing}): {@code angle ← aim + (angle − aim) · e^(−dt/τ)}, the yaw the shorter way
 *       round ({@link SmoothLook}). No roll.</li>
 *   <li><b>Fly.</b> The wished direction {@code ŵ} is the normalised sum of the keys' directions: W/S along the
 *       view {@code f = (sin yaw cos pitch, sin pitch, −cos yaw cos pitch)} ({@link CameraMath#forward}), A/D
 *       along {@code r = (cos yaw, 0, sin yaw)}, Space and C/Left Ctrl along Y. The wished velocity is
 *       {@code u = s · ŵ} with {@code s = flySpeed}, times {@code boost} while Shift is held. The velocity follows
 *       the linear ODE {@code dv/dt = a · (u − v)} with {@code a = camera.acceleration} while a key is held, and
 *       {@code dv/dt = −k · v} with {@code k = camera.damping} once all are released, integrated exactly
 *       ({@link InertialMotion}):
 *       <pre>
 *   v ← u + (v − u) · e^(−a·dt)        (held: the speed tends to s, never beyond it)
 *   v ← v · e^(−k·dt)                  (released: a glide to a halt, 1/k seconds per factor e)
 *   x ← x + u·dt + (v₀ − u) · (1 − e^(−a·dt)) / a
 *       </pre>
 *       The exact solution makes the path independent of the step: at 60 or 120 updates a second the camera
 *       ends in the same place. The eye never goes below the ground plus {@link #MIN_CLEARANCE}.</li>
 *   <li><b>Walk.</b> As flying, but horizontal: W/S along the heading {@code (sin yaw, 0, −cos yaw)}, A/D along
 *       {@code r}, {@code s = walkSpeed}, times {@code runFactor} with Shift, and the rate {@code a} both to start
 *       and to stop (feet stop a walker; nothing stops a flyer but air). The eye follows the ground:
 *       {@code y ← y_t + (y − y_t) · e^(−dt/τ_step)} with {@code y_t = h(x, z) + eyeHeight}, so a step in the
 *       ground eases in over about 3 τ_step instead of jolting the view, and {@code y} never drops below
 *       {@code h(x, z) + MIN_CLEARANCE}, as the director keeps every eye ({@link CameraSystem}). {@code h} is the world's {@link HeightField}, flat at 0
 *       without one. Switching to walk (key V) therefore drops the camera to the ground, quickly but
 *       smoothly.</li>
 *   <li><b>Pose.</b> the new pose {@code (x, y, z, yaw, pitch, camera.fov)}, which the director writes into the {@link Camera}.</li>
 * </ol>
 *
 * <h2>Starting</h2>
 * The controller keeps no position of its own, only the velocity, the look aim and the mode. {@link #startAt} aims at
 * a pose's view and stops (a teleport carries no momentum), so taking over from a path or a fixed pose never swings
 * or slides the camera.
 *
 * <h2>Limits</h2>
 * The ground is sampled under the eye only: walking into a cliff steeper than the near plane's reach can show the
 * rock's inside for a frame; there are no collisions with anything but the ground.
 */
public final class CameraController {

    /** Least height of the eye above the ground, metres: the near plane's distance, so it does not cut the ground. */
    public static final double MIN_CLEARANCE = Camera.NEAR;

    private final SmoothLook look = new SmoothLook();
    private final InertialMotion motion = new InertialMotion();
    private CameraMode mode = CameraSettings.DEFAULTS.mode();
    /** The mode setting last seen, so a change of {@code camera.mode} at run time takes effect; null before the first. */
    private CameraMode settingMode;

    /** Takes over at {@code pose}: the look aims at its view, the camera is at rest. */
    public void startAt(CameraPose pose) {
        look.aimAt(pose.yaw(), pose.pitch());
        motion.stop();
    }

    /**
     * One fixed step of the motion model from {@code pose}.
     *
     * @param pose     where the camera is
     * @param controls the keys and mouse of this step
     * @param ground   the terrain ({@link HeightField#FLAT} without one)
     * @param settings {@code camera.*}
     * @param step     seconds
     * @return the new pose
     */
    public CameraPose step(CameraPose pose, CameraControls controls, HeightField ground, CameraSettings settings,
                           double step) {
        // 1. the mode from the settings or key V
        if (settings.mode() != settingMode) {
            settingMode = settings.mode();
            setMode(settingMode);
        }
        if (controls.toggleMode()) {
            setMode(mode.toggled());
        }

        // 2. look: move the aim, then follow it
        look.turn(controls.mouseDx() * settings.mouseSensitivity() + controls.turnRight() * settings.turnSpeed() * step,
                -controls.mouseDy() * settings.mouseSensitivity() + controls.turnUp() * settings.turnSpeed() * step);
        double[] view = look.follow(pose.yaw(), pose.pitch(), step, settings.lookSmoothing());
        double yaw = view[0];
        double pitch = view[1];

        // 3. move
        Vector3d eye = new Vector3d(pose.x(), pose.y(), pose.z());
        if (mode == CameraMode.FLY) {
            fly(eye, yaw, pitch, controls, ground, settings, step);
        } else {
            walk(eye, yaw, controls, ground, settings, step);
        }
        return new CameraPose(eye.x, eye.y, eye.z, yaw, pitch, settings.fov());
    }

    private void fly(Vector3d eye, double yaw, double pitch, CameraControls c, HeightField ground, CameraSettings s,
                     double dt) {
        Vector3d wish = CameraMath.forward(yaw, pitch).mul(c.forward())
                .add(CameraMath.right(yaw).mul(c.right()))
                .add(0, c.up(), 0);
        boolean steering = wish.lengthSquared() > 0;
        if (steering) {
            wish.normalize(s.flySpeed() * (c.fast() ? s.boost() : 1));
        }
        eye.add(motion.step(wish, steering ? s.acceleration() : s.damping(), dt));
        double floor = ground.heightAt(eye.x, eye.z) + MIN_CLEARANCE;
        if (eye.y < floor) {
            eye.y = floor;
            if (motion.velocity().y() < 0) {
                motion.stopVertical();
            }
        }
    }

    private void walk(Vector3d eye, double yaw, CameraControls c, HeightField ground, CameraSettings s, double dt) {
        Vector3d wish = CameraMath.flatForward(yaw).mul(c.forward()).add(CameraMath.right(yaw).mul(c.right()));
        if (wish.lengthSquared() > 0) {
            wish.normalize(s.walkSpeed() * (c.fast() ? s.runFactor() : 1));
        }
        motion.stopVertical();
        Vector3d moved = motion.step(wish, s.acceleration(), dt);
        eye.x += moved.x;
        eye.z += moved.z;
        double h = ground.heightAt(eye.x, eye.z);
        double target = h + s.eyeHeight();
        eye.y = target + (eye.y - target) * CameraMath.decayWithTimeConstant(s.stepSmoothing(), dt);
        eye.y = Math.max(eye.y, h + MIN_CLEARANCE);
    }

    /** The current movement mode. */
    public CameraMode mode() {
        return mode;
    }

    /** Switches fly or walk; a change of mode stops the camera (walking starts from rest, on the ground). */
    public void setMode(CameraMode newMode) {
        if (newMode != mode) {
            mode = newMode;
            motion.stop();
        }
    }

    /** The camera's velocity, m/s, e.g. for a speed readout (a read-only view). */
    public Vector3dc velocity() {
        return motion.velocity();
    }
}

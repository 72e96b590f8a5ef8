package org.openworld.engine.camera;

import java.util.Optional;
import org.openworld.engine.core.HeightField;

/**
 * Who moves the camera, as a world resource that the camera system (the director) reads at every update: the user's
 * controls, a camera path, or a fixed pose. Commands and the window say where the camera should be by setting one
 * under this interface's class ({@code world.setResource(CameraDirection.class, CameraDirection.fixed(pose))});
 * only the director writes the {@link Camera}, and it does so first in the frame, before any system reads the pose.
 * Each direction set is taken up once, at the next update: a new one, even equal to the last, starts over (the
 * controls stop, a replay goes back to its start).
 *
 * <p>Each kind computes its own pose ({@link #pose}), so the director has no branch per kind and a new kind (an
 * orbit around a point, a follow camera) is one more record here.
 */
public sealed interface CameraDirection {

    /**
     * What the director knows at an update.
     *
     * @param current    the camera's pose before this update
     * @param updates    updates since this direction was taken up: 0 at the first
     * @param step       the fixed step, seconds
     * @param ground     the terrain ({@link HeightField#FLAT} without one)
     * @param controller the user's controls, with their motion state
     * @param input      this update's keys and mouse
     * @param settings   {@code camera.*}
     */
    record Cue(CameraPose current, long updates, double step, HeightField ground, CameraController controller,
               CameraControls input, CameraSettings settings) {
    }

    /** Where the camera is at this update. */
    CameraPose pose(Cue cue);

    /**
     * The direction that goes on with this one in a rebuilt world whose camera was at {@code current}: the controls
     * from there; a path or a pose as they are (a replay starts again).
     */
    default CameraDirection carriedOver(CameraPose current) {
        return this;
    }

    /** The user flies or walks, starting from {@code from} (empty: from wherever the camera is), at rest. */
    record Controls(Optional<CameraPose> from) implements CameraDirection {

        @Override
        public CameraPose pose(Cue cue) {
            CameraPose start = cue.current();
            if (cue.updates() == 0) {
                start = from.orElse(start);
                cue.controller().startAt(start);
            }
            return cue.controller().step(start, cue.input(), cue.ground(), cue.settings(), cue.step());
        }

        @Override
        public CameraDirection carriedOver(CameraPose current) {
            return controlsFrom(current);
        }
    }

    /**
     * A camera path: at the first update the pose is the path's at {@code start} (seconds on the path's clock, the
     * file's time column), and each update moves the path's clock on by {@code rate} steps (1 plays the path at the
     * simulation's speed, 0 holds one moment). Past the last key the path holds its last pose, or starts again from
     * its first key when {@code loop}.
     */
    record Replay(CameraPath path, double start, double rate, boolean loop) implements CameraDirection {

        public Replay {
            if (!Double.isFinite(start) || !Double.isFinite(rate) || rate < 0) {
                throw new IllegalArgumentException("a replay starts at a finite time (" + start
                        + " s) and moves at a rate of 0 or more (" + rate + ")");
            }
        }

        /** The path at {@code start + rate · updates · step}: a product, not a running sum, so no rounding drifts. */
        @Override
        public CameraPose pose(Cue cue) {
            double t = start + rate * cue.updates() * cue.step();
            if (loop && path.duration() > 0 && t > path.endTime()) {
                t = path.startTime() + (t - path.startTime()) % path.duration();
            }
            return path.sample(t, cue.ground());
        }
    }

    /** One pose, held still: a screenshot, a figure. */
    record Fixed(CameraPose pose) implements CameraDirection {

        @Override
        public CameraPose pose(Cue cue) {
            return pose;
        }
    }

    /** The user's controls from where the camera is now. */
    static CameraDirection controls() {
        return new Controls(Optional.empty());
    }

    /** The user's controls from {@code pose} (the window's start, a rebuilt world). */
    static CameraDirection controlsFrom(CameraPose pose) {
        return new Controls(Optional.of(pose));
    }

    /** The path played from {@code start} seconds on its clock at the simulation's speed. */
    static CameraDirection play(CameraPath path, double start, boolean loop) {
        return new Replay(path, start, 1, loop);
    }

    /** The path's pose at {@code seconds} on its clock, held. */
    static CameraDirection hold(CameraPath path, double seconds) {
        return new Replay(path, seconds, 0, false);
    }

    static CameraDirection fixed(CameraPose pose) {
        return new Fixed(pose);
    }
}

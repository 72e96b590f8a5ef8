package org.openworld.demo;

import java.util.Locale;
import java.util.Optional;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraController;
import org.openworld.engine.camera.CameraDirection;
import org.openworld.engine.camera.CameraPath;
import org.openworld.engine.camera.CameraPathFormatException;
import org.openworld.engine.camera.CameraPathParser;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.camera.CameraSystem;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.World;

/** Turns {@link PoseOptions} into a camera pose: an explicit {@code --camera}, a path moment, or the default view. */
final class Poses {

    private Poses() {
    }

    /**
     * The path named by {@code --path}, parsed before any window opens so a broken file fails fast. {@code --at}
     * picks a moment of that path, so it is refused without one (it would be silently ignored) and must be a finite
     * number of seconds.
     */
    static Optional<CameraPath> loadPath(PoseOptions options) throws CameraPathFormatException {
        if (options.camera != null && options.path != null) {
            throw new UserError("--camera and --path exclude each other");
        }
        if (options.at != null && options.path == null) {
            throw new UserError("--at picks a moment of a camera path: give --path FILE with it, or leave it out");
        }
        if (options.path == null) {
            return Optional.empty();
        }
        CameraPath path = CameraPathParser.parse(options.path);
        if (!Double.isFinite(options.at())) {
            throw new UserError(String.format(Locale.ROOT, "--at %s: expected a time in seconds, e.g. within the "
                    + "path's keys %s .. %s", options.at, path.startTime(), path.endTime()));
        }
        return Optional.of(path);
    }

    /**
     * A still picture's direction: the {@code --camera} pose, the path's pose at {@code --at}, or the default view over
     * this world's ground.
     */
    static CameraDirection still(PoseOptions options, Optional<CameraPath> path, World world) {
        if (options.camera != null) {
            return CameraDirection.fixed(options.camera);
        }
        return path.map(p -> CameraDirection.hold(p, options.at()))
                .orElse(CameraDirection.fixed(DemoScene.defaultPose(world)));
    }

    /**
     * What the camera director did at this frame's update, if it lifted the eye out of the ground (a pose or a path
     * below it; {@link CameraSystem#LIFTED}): one line saying where the eye is now.
     */
    static Optional<String> lifted(World world) {
        Double metres = world.resource(Counters.class).get(CameraSystem.LIFTED);
        if (metres == null) {
            return Optional.empty();
        }
        CameraPose eye = world.resource(Camera.class).pose();
        double ground = eye.y() - CameraController.MIN_CLEARANCE;
        return Optional.of(String.format(Locale.ROOT, "the eye at y=%.1f m is below the ground at x=%.1f, z=%.1f (%.1f m)"
                + " or nearer it than the near plane (%.1f m): lifted to y=%.1f m", eye.y() - metres, eye.x(), eye.z(),
                ground, CameraController.MIN_CLEARANCE, eye.y()));
    }

    /** Tells the world's camera director to follow {@code direction} from the next update on. */
    static void direct(World world, CameraDirection direction) {
        world.setResource(CameraDirection.class, direction);
    }
}

package org.openworld.demo;

import java.util.Optional;
import org.openworld.engine.camera.CameraDirection;
import org.openworld.engine.camera.CameraPath;
import org.openworld.engine.camera.CameraPathFormatException;
import org.openworld.engine.camera.CameraPathParser;
import org.openworld.engine.core.World;

/** Turns {@link PoseOptions} into a camera pose: an explicit {@code --camera}, a path moment, or the default view. */
final class Poses {

    private Poses() {
    }

    /** The path named by {@code --path}, parsed before any window opens so a broken file fails fast. */
    static Optional<CameraPath> loadPath(PoseOptions options) throws CameraPathFormatException {
        if (options.camera != null && options.path != null) {
            throw new UserError("--camera and --path exclude each other");
        }
        return options.path == null ? Optional.empty() : Optional.of(CameraPathParser.parse(options.path));
    }

    /** A still picture's direction: the {@code --camera} pose, the path's pose at {@code --at}, or the default view. */
    static CameraDirection still(PoseOptions options, Optional<CameraPath> path) {
        if (options.camera != null) {
            return CameraDirection.fixed(options.camera);
        }
        return path.map(p -> CameraDirection.hold(p, options.at))
                .orElse(CameraDirection.fixed(DemoScene.DEFAULT_POSE));
    }

    /** Tells the world's camera director to follow {@code direction} from the next update on. */
    static void direct(World world, CameraDirection direction) {
        world.setResource(CameraDirection.class, direction);
    }
}

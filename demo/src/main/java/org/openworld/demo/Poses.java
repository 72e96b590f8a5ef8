package org.openworld.demo;

import java.util.Optional;
import org.openworld.engine.camera.CameraPath;
import org.openworld.engine.camera.CameraPathFormatException;
import org.openworld.engine.camera.CameraPathParser;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.HeightField;
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

    static CameraPose resolve(PoseOptions options, Optional<CameraPath> path, World world) {
        if (options.camera != null) {
            return options.camera;
        }
        if (path.isPresent()) {
            HeightField ground = world.findResource(HeightField.class).orElse(HeightField.FLAT);
            return path.get().sample(options.at, ground);
        }
        return DemoScene.DEFAULT_POSE;
    }
}

package org.openworld.engine.camera;

import java.util.List;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.core.World;
import org.openworld.engine.input.InputState;
import org.openworld.engine.settings.Settings;

/** A world with just what the camera system needs, driven step by step without GL. */
final class CameraRig {

    final World world = new World();
    final Settings settings = new Settings(List.of(CameraSystem.SETTINGS));
    final InputState input = new InputState();
    final Camera camera = new Camera();
    final CameraSystem system = new CameraSystem();

    CameraRig() {
        world.setResource(settings);
        world.setResource(input);
        world.setResource(camera);
    }

    /** Hands the camera to the user's controls at this pose, from the next update on. */
    CameraRig at(double x, double y, double z, double yaw, double pitch) {
        return direct(CameraDirection.controlsFrom(new CameraPose(x, y, z, yaw, pitch, CameraPose.DEFAULT_FOV)));
    }

    CameraRig direct(CameraDirection direction) {
        world.setResource(CameraDirection.class, direction);
        return this;
    }

    CameraRig ground(HeightField field) {
        world.setResource(HeightField.class, field);
        return this;
    }

    CameraRig set(String key, String value) {
        settings.set(key, value);
        return this;
    }

    /** Runs whole steps covering {@code seconds} of simulation time. */
    CameraRig run(double seconds, double step) {
        long steps = Math.round(seconds / step);
        for (long i = 0; i < steps; i++) {
            system.update(world, step);
        }
        return this;
    }

    CameraRig run(double seconds) {
        return run(seconds, 1.0 / 60);
    }

    CameraPose pose() {
        return camera.pose();
    }

    double speed() {
        return system.controller().velocity().length();
    }
}

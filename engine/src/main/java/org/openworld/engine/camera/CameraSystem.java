package org.openworld.engine.camera;

import java.util.List;
import org.openworld.engine.core.Counter;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.core.World;
import org.openworld.engine.input.InputState;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsGroup;

/**
 * The camera's director: the one system that writes the {@link Camera}. At every fixed update it reads the world's
 * {@link CameraDirection} and moves the camera as it says:
 * <ul>
 *   <li>{@link CameraDirection.Controls}: the user flies or walks ({@link CameraController}, its motion model);</li>
 *   <li>{@link CameraDirection.Replay}: the pose of a {@link CameraPath} at a time that moves on with the steps
 *       (a benchmark, the window's {@code --path}) or stands still (a shot of a path's moment);</li>
 *   <li>{@link CameraDirection.Fixed}: one pose ({@code shot --camera}, the figures).</li>
 * </ul>
 * A world without a direction is under the user's controls. Whatever the direction, the eye is kept
 * {@link CameraController#MIN_CLEARANCE} above the ground under it: a fixed pose or a path may put it inside the
 * relief, where the ground is seen from below, its back faces culled, and only the slopes turned towards the eye are
 * drawn, as ribbons and arches of rock hanging in the air. A lifted eye is reported in the frame's counter
 * {@link #LIFTED}, metres, so that a command can say so. Because it writes the camera, the frame order puts it
 * before every system that reads the camera (the sky's tables and aerial perspective, the terrain's tiles, the shadow
 * fit): whatever moves the camera, every system of a frame sees the same pose, the first frame included, and
 * {@code openworld info --frame} prints the order that really runs.
 *
 * <p><b>Cost.</b> Constant per update: one controller step, or one path sample (a binary search over keys).
 */
public final class CameraSystem implements EngineSystem {

    public static final SettingsGroup<CameraSettings> SETTINGS =
            SettingsGroup.of("camera", CameraSettings.class, CameraSettings.DEFAULTS);

    /** The counter of a frame whose eye was lifted over the ground: by how many metres. */
    public static final Counter LIFTED = Counter.of("camera", "lifted");

    /** Stands in for the input resource in headless runs, which have none. */
    private static final InputState NO_INPUT = new InputState();

    private final CameraController controller = new CameraController();
    /** The direction being followed, null before the first update; a different object is taken up anew. */
    private CameraDirection following;
    /** Updates since {@link #following} was taken up. */
    private long updates;

    @Override
    public SystemSpec spec() {
        return SystemSpec.named("camera")
                .reads(CameraDirection.class, InputState.class, HeightField.class, Settings.class)
                .writes(Camera.class);
    }

    @Override
    public List<SettingsGroup<?>> settings() {
        return List.of(SETTINGS);
    }

    /** Applies the fov setting at once, so a camera under the controls has it from the first frame. */
    @Override
    public void init(EngineContext context) {
        Camera camera = context.world().resource(Camera.class);
        CameraPose p = camera.pose();
        camera.setPose(new CameraPose(p.x(), p.y(), p.z(), p.yaw(), p.pitch(),
                context.settings().get(CameraSettings.class).fov()));
    }

    @Override
    public void update(World world, double step) {
        Camera camera = world.resource(Camera.class);
        HeightField ground = world.findResource(HeightField.class).orElse(HeightField.FLAT);
        CameraDirection direction = world.findResource(CameraDirection.class).orElse(null);
        if (direction == null) {
            direction = CameraDirection.controls();
            world.setResource(CameraDirection.class, direction);
        }

        // 1. a new direction is taken up from its first update
        if (direction != following) {
            following = direction;
            updates = 0;
        }

        // 2. this update's pose, from the direction
        CameraPose pose = direction.pose(new CameraDirection.Cue(camera.pose(), updates++, step, ground, controller,
                CameraControls.read(world.findResource(InputState.class).orElse(NO_INPUT)),
                world.resource(Settings.class).get(CameraSettings.class)));

        // 3. never inside the relief: the eye at least the near plane's distance above the ground
        double floor = ground.heightAt(pose.x(), pose.z()) + CameraController.MIN_CLEARANCE;
        if (pose.y() < floor) {
            world.resource(Counters.class).put(LIFTED, floor - pose.y());
            pose = new CameraPose(pose.x(), floor, pose.z(), pose.yaw(), pose.pitch(), pose.fov());
        }
        camera.setPose(pose);
    }

    /** The user's controls: their mode (fly or walk) and velocity, e.g. for a readout. */
    public CameraController controller() {
        return controller;
    }
}

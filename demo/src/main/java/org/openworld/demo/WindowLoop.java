package org.openworld.demo;

import static org.lwjgl.glfw.GLFW.*;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Clock;
import java.util.List;
import java.util.Optional;
import org.openworld.engine.Engine;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPath;
import org.openworld.engine.camera.CameraPathRecorder;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.input.InputState;

/**
 * The interactive loop: GLFW events into the world's {@link InputState}, fixed-step updates for the real time
 * that passed, one render, the picture to the screen. Keys the loop itself handles (the camera system handles
 * movement): Esc, Tab or the right mouse button for mouse look, R to record a path, T, [, ], - and = for the day
 * cycle ({@link DayCycle}), F5 to reload shaders (with {@code --dev}), F1 to print the controls.
 */
final class WindowLoop {

    static final String CONTROLS = """
            Controls
              W A S D         move (fly: along the view; walk: on the ground)
              Space / C       up / down (fly)
              Shift           faster
              Arrow keys      turn
              Right mouse     hold to look around (Tab toggles it on and off)
              V               fly / walk
              T               pause / resume the day cycle
              [ / ]           a quarter hour earlier / later
              - / =           day cycle half / twice as fast
              R               start / stop recording a camera path (saved under assets/paths/)
              F5              reload shaders from ./shaders (with --dev)
              F1              print these controls
              Esc             release the mouse, or quit""";

    /** Where recorded paths are saved, relative to the working directory. */
    static final Path RECORDINGS = Path.of("assets", "paths");
    /** How often the title bar's frame rate is refreshed, seconds. */
    private static final double TITLE_INTERVAL = 0.5;

    private final Launch launch;
    private final Engine engine;
    private final Optional<CameraPath> replay;
    private final InputState input = new InputState();
    private final DayCycle day = new DayCycle();
    private CameraPathRecorder recorder;
    private boolean lookToggled;
    private double lastX = Double.NaN;
    private double lastY = Double.NaN;

    WindowLoop(Launch launch, Optional<CameraPath> replay, PoseOptions pose) {
        this.launch = launch;
        this.engine = launch.engine;
        this.replay = replay;
        engine.world().setResource(input);
        engine.world().resource(Camera.class).setPose(Poses.resolve(pose, replay, engine.world()));
    }

    void run() {
        long window = launch.gl.window();
        installCallbacks(window);
        System.out.println(CONTROLS);
        double last = glfwGetTime();
        double titleAt = last;
        int framesSinceTitle = 0;
        Camera camera = engine.world().resource(Camera.class);
        HeightField ground = engine.world().findResource(HeightField.class).orElse(HeightField.FLAT);
        while (!launch.gl.shouldClose()) {
            glfwPollEvents();
            int[] size = launch.gl.framebufferSize();
            if (size[0] == 0 || size[1] == 0) {
                glfwWaitEvents(); // minimised: nothing to draw until it comes back
                last = glfwGetTime();
                continue;
            }
            engine.resize(size[0], size[1]);
            double now = glfwGetTime();
            engine.advance(now - last);
            last = now;
            if (replay.isPresent()) {
                CameraPath path = replay.get();
                camera.setPose(path.sample(engine.simTime() % path.duration(), ground));
            }
            if (recorder != null) {
                recorder.record(engine.simTime(), camera.pose());
            }
            engine.render();
            engine.present(size[0], size[1]);
            launch.gl.swapBuffers();
            engine.collectFrames(false, r -> { });
            framesSinceTitle++;
            if (now - titleAt >= TITLE_INTERVAL) {
                double ms = (now - titleAt) * 1000 / framesSinceTitle;
                glfwSetWindowTitle(window, String.format("OpenWorld - %.0f fps (%.1f ms) - %s%s", 1000 / ms, ms,
                        DayCycle.describe(time()),
                        recorder != null ? " - recording" : ""));
                titleAt = now;
                framesSinceTitle = 0;
            }
        }
        if (recorder != null) {
            stopRecording();
        }
    }

    private void installCallbacks(long window) {
        glfwSetKeyCallback(window, (w, key, scancode, action, mods) -> {
            if (action == GLFW_PRESS) {
                input.keyDown(key);
                onPress(window, key);
            } else if (action == GLFW_REPEAT && (key == GLFW_KEY_LEFT_BRACKET || key == GLFW_KEY_RIGHT_BRACKET)) {
                onPress(window, key); // held: keep scrubbing
            } else if (action == GLFW_RELEASE) {
                input.keyUp(key);
            }
        });
        glfwSetMouseButtonCallback(window, (w, button, action, mods) -> {
            if (button == GLFW_MOUSE_BUTTON_RIGHT && !lookToggled) {
                setLooking(window, action == GLFW_PRESS);
            }
        });
        glfwSetCursorPosCallback(window, (w, x, y) -> {
            if (input.looking() && !Double.isNaN(lastX)) {
                input.mouseMoved(x - lastX, y - lastY);
            }
            lastX = x;
            lastY = y;
        });
    }

    private void onPress(long window, int key) {
        switch (key) {
            case GLFW_KEY_ESCAPE -> {
                if (input.looking()) {
                    lookToggled = false;
                    setLooking(window, false);
                } else {
                    glfwSetWindowShouldClose(window, true);
                }
            }
            case GLFW_KEY_TAB -> {
                lookToggled = !lookToggled;
                setLooking(window, lookToggled);
            }
            case GLFW_KEY_R -> {
                if (recorder == null) {
                    recorder = new CameraPathRecorder(CameraPathRecorder.DEFAULT_INTERVAL);
                    System.out.println("recording camera path (R again to stop and save)");
                } else {
                    stopRecording();
                }
            }
            case GLFW_KEY_T -> setTime(day.togglePause(time()));
            case GLFW_KEY_LEFT_BRACKET -> setTime(day.scrub(time(), -1));
            case GLFW_KEY_RIGHT_BRACKET -> setTime(day.scrub(time(), 1));
            case GLFW_KEY_MINUS -> setTime(day.changeSpeed(time(), 0.5));
            case GLFW_KEY_EQUAL -> setTime(day.changeSpeed(time(), 2));
            case GLFW_KEY_F5 -> reloadShaders();
            case GLFW_KEY_F1 -> System.out.println(CONTROLS);
            default -> { }
        }
    }

    private TimeOfDay time() {
        return engine.world().resource(TimeOfDay.class);
    }

    private void setTime(TimeOfDay t) {
        engine.world().setResource(t);
    }

    private void setLooking(long window, boolean looking) {
        input.setLooking(looking);
        glfwSetInputMode(window, GLFW_CURSOR, looking ? GLFW_CURSOR_DISABLED : GLFW_CURSOR_NORMAL);
        lastX = Double.NaN;
    }

    private void stopRecording() {
        CameraPathRecorder done = recorder;
        recorder = null;
        if (done.size() < 2) {
            System.out.println("recording too short to save (needs two keyframes)");
            return;
        }
        try {
            Path saved = done.save(RECORDINGS, Clock.systemDefaultZone());
            System.out.println("saved " + saved + " (" + done.size() + " keyframes); replay with --path " + saved);
        } catch (IOException e) {
            System.err.println("could not save the recorded path: " + e.getMessage());
        }
    }

    private void reloadShaders() {
        if (!launch.devShaders) {
            System.out.println("shaders come from the jar; start with --dev to edit ./shaders and reload them with F5");
            return;
        }
        List<String> errors = engine.shaders().reloadAll();
        if (errors.isEmpty()) {
            System.out.println("shaders reloaded");
        } else {
            errors.forEach(e -> System.err.println("shader reload failed, keeping the old program:\n" + e));
        }
    }
}

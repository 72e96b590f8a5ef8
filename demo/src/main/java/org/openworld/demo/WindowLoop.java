package org.openworld.demo;

import static org.lwjgl.glfw.GLFW.*;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Clock;
import java.util.List;
import java.util.Optional;
import org.openworld.engine.camera.CameraDirection;
import org.openworld.engine.Engine;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPath;
import org.openworld.engine.camera.CameraPathRecorder;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.input.InputState;

/**
 * The interactive loop: GLFW events to the Dear ImGui layer ({@link Gui}) and then, unless it took them, into the
 * world's {@link InputState}; fixed-step updates for the real time that passed; one render; the picture to the
 * screen with the panel, HUD and controls over it. Keys the loop itself handles (the camera system handles
 * movement): Esc, Tab or the right mouse button for mouse look, R to record a path, T, [, ], - and = for the day
 * cycle ({@link DayCycle}), F1 to F3 for the controls, settings panel and HUD, F5 to reload shaders (with
 * {@code --dev}).
 */
final class WindowLoop implements SettingsPanel.Host {

    /** Every key binding; the README's table lists the same. */
    static final String CONTROLS = """
            W A S D         move (fly: along the view; walk: on the ground)
            Space / C       up / down (fly)
            Shift           faster
            Arrow keys      turn
            Right mouse     hold to look around (Tab toggles it on and off)
            V               fly / walk
            T               pause / resume the day cycle
            [ / ]           a quarter hour earlier / later (hold to scrub)
            - / =           day cycle half / twice as fast
            R               start / stop recording a camera path (saved under assets/paths/)
            F1              show / hide these controls
            F2              show / hide the settings panel
            F3              show / hide the HUD (frame times, GPU time per pass, counters)
            F5              reload shaders from ./shaders (with --dev)
            Esc             release the mouse, or quit""";

    /** Where recorded paths are saved, relative to the working directory. */
    static final Path RECORDINGS = Path.of("assets", "paths");
    /** How often the title bar's frame rate is refreshed, seconds. */
    private static final double TITLE_INTERVAL = 0.5;

    private final Launch launch;
    private final Optional<CameraPath> replay;
    private final Hud hud = new Hud();
    private final SettingsPanel panel;
    /** The panel, HUD and controls; empty where Dear ImGui's natives do not load (the window still runs). */
    private Optional<Gui> gui = Optional.empty();
    private final InputState input = new InputState();
    private final DayCycle day = new DayCycle();
    private CameraPathRecorder recorder;
    private boolean lookToggled;
    private double lastX = Double.NaN;
    private double lastY = Double.NaN;

    WindowLoop(Launch launch, Optional<CameraPath> replay, PoseOptions pose) {
        this.launch = launch;
        this.replay = replay;
        engine().world().setResource(input);
        Poses.direct(engine().world(), replay
                .map(path -> CameraDirection.play(path, pose.at(), true))
                .orElse(CameraDirection.controlsFrom(pose.explicitPose()
                        .orElseGet(() -> DemoScene.defaultPose(engine().world())))));
        panel = new SettingsPanel(engine().settings(), this);
    }

    private Engine engine() {
        return launch.engine;
    }

    void run() {
        long window = launch.gl.window();
        installCallbacks(window);
        startGui(window);
        double last = glfwGetTime();
        double titleAt = last;
        int framesSinceTitle = 0;
        while (!launch.gl.shouldClose()) {
            glfwPollEvents();
            int[] size = launch.gl.framebufferSize();
            if (size[0] == 0 || size[1] == 0) {
                glfwWaitEvents(); // minimised: nothing to draw until it comes back
                last = glfwGetTime();
                continue;
            }
            panel.rebuildIfAsked();
            Engine engine = engine();
            Camera camera = engine.world().resource(Camera.class);
            engine.resize(size[0], size[1]);
            double now = glfwGetTime();
            engine.advance(now - last);
            last = now;
            if (recorder != null) {
                recorder.record(engine.simTime(), camera.pose());
            }
            engine.render();
            gui.ifPresent(g -> engine.drawOver(g::draw));
            engine.present(size[0], size[1]);
            launch.gl.swapBuffers();
            engine.collectFrames(false, hud::add);
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
        gui.ifPresent(Gui::close);
    }

    /** The panel, HUD and controls, or a line saying why the window runs without them. */
    private void startGui(long window) {
        try {
            gui = Optional.of(new Gui(window, panel, hud));
            System.out.println("F1 shows the controls, F2 the settings panel, F3 the HUD");
        } catch (LinkageError e) {
            System.err.println("the settings panel and HUD are not available: Dear ImGui's native library did not "
                    + "load on this platform (" + e.getMessage() + "); the window runs without them. Controls:\n"
                    + CONTROLS);
        }
    }

    @Override
    public void rebuild() {
        System.out.println("rebuilding the world...");
        launch.rebuild();
        engine().world().setResource(input);
    }

    private void installCallbacks(long window) {
        glfwSetKeyCallback(window, (w, key, scancode, action, mods) -> {
            gui.ifPresent(g -> g.key(w, key, scancode, action, mods));
            if (action == GLFW_RELEASE) {
                input.keyUp(key); // always, so a key pressed before a text field took the keyboard is let go
                return;
            }
            if (gui.isPresent() && gui.get().wantsKeyboard()) {
                return;
            }
            if (action == GLFW_PRESS) {
                input.keyDown(key);
                onPress(window, key);
            } else if (action == GLFW_REPEAT && (key == GLFW_KEY_LEFT_BRACKET || key == GLFW_KEY_RIGHT_BRACKET)) {
                onPress(window, key); // held: keep scrubbing
            }
        });
        glfwSetCharCallback(window, (w, codepoint) -> gui.ifPresent(g -> g.character(w, codepoint)));
        glfwSetScrollCallback(window, (w, dx, dy) -> gui.ifPresent(g -> g.scroll(w, dx, dy)));
        glfwSetMouseButtonCallback(window, (w, button, action, mods) -> {
            gui.ifPresent(g -> g.mouseButton(w, button, action, mods));
            boolean overGui = gui.isPresent() && gui.get().wantsMouse() && !input.looking();
            if (button == GLFW_MOUSE_BUTTON_RIGHT && !lookToggled && !(overGui && action == GLFW_PRESS)) {
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
            case GLFW_KEY_F1 -> gui.ifPresentOrElse(Gui::toggleControls, () -> System.out.println(CONTROLS));
            case GLFW_KEY_F2 -> gui.ifPresent(Gui::togglePanel);
            case GLFW_KEY_F3 -> gui.ifPresent(Gui::toggleHud);
            default -> { }
        }
    }

    @Override
    public TimeOfDay time() {
        return engine().world().resource(TimeOfDay.class);
    }

    @Override
    public void setTime(TimeOfDay t) {
        engine().world().setResource(t);
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
        List<String> errors = engine().shaders().reloadAll();
        if (errors.isEmpty()) {
            System.out.println("shaders reloaded");
        } else {
            errors.forEach(e -> System.err.println("shader reload failed, keeping the old program:\n" + e));
        }
    }
}

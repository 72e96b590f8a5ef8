package org.openworld.demo;

import static org.lwjgl.glfw.GLFW.glfwSetWindowSize;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.openworld.engine.antialias.AntialiasSettings;
import org.openworld.engine.camera.CameraDirection;
import org.openworld.engine.gl.Image;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code openworld shot}: one image, headless by default. */
@Command(name = "shot", mixinStandardHelpOptions = true, description = "Render one image to a PNG or JPEG file (headless unless --window).")
final class ShotCommand implements Callable<Integer> {

    @Mixin
    RenderOptions render;

    @Mixin
    PoseOptions pose;

    @Option(names = "--out", paramLabel = "FILE.png", required = true,
            description = "The picture to write: a PNG, or a JPEG for a name ending in .jpg or .jpeg.")
    Path out;

    @Option(names = "--force", description = "Overwrite --out even if it is a file other than a PNG.")
    boolean force;

    @Option(names = "--ui", description = "Draw the window's settings panel and HUD over the picture, as the window "
            + "shows them (for screenshots).")
    boolean ui;

    /** Frames rendered before a --ui shot, so the HUD has timings to show (they arrive a frame or two late). */
    private static final int UI_FRAMES = 4;

    /** What one shot made: the picture written to {@code --out} and the OpenGL it was made with. */
    record Result(Image image, String renderer, String contextMode, double ms) {
    }

    @Override
    public Integer call() throws Exception {
        Result shot = take();
        System.out.printf("wrote %s (%dx%d) in %.0f ms on %s, %s%n", out, shot.image().width(), shot.image().height(),
                shot.ms(), shot.renderer(), shot.contextMode());
        return 0;
    }

    /**
     * Renders the image these options describe and writes it to {@code --out} (checked first, {@link Outputs#png};
     * written whole or not at all, {@link Image#write}): the whole of {@code shot}, less its printed line, so {@code openworld figures} makes each picture exactly as its printed command would.
     */
    Result take() throws Exception {
        var path = Poses.loadPath(pose);
        Outputs.picture(out, force);
        long start = System.nanoTime();
        try (Launch launch = ui ? Launch.startWithGui(render, render.windowed(false), "OpenWorld shot")
                : Launch.start(render, render.windowed(false), "OpenWorld shot")) {
            prepare(launch, Poses.still(pose, path, launch.engine.world()));
            Poses.lifted(launch.engine.world()).ifPresent(line -> System.err.println("shot: " + line));
            if (ui) {
                renderWithUi(launch);
            } else {
                renderSettled(launch);
            }
            Image image = opaque(launch.engine.readImage());
            image.write(out);
            return new Result(image, launch.gl.renderer(), launch.gl.mode().toString(),
                    (System.nanoTime() - start) / 1e6);
        }
    }

    /**
     * Points the camera and runs the one update of a shot: the director writes the pose first in the frame order, so
     * every system's update (the sky's tables for the camera's altitude, the terrain's tiles, the shadow fit) sees
     * the pose the picture is taken from.
     */
    static void prepare(Launch launch, CameraDirection direction) {
        Poses.direct(launch.engine.world(), direction);
        launch.engine.update();
    }

    /**
     * Renders the frames a still picture needs ({@code AntialiasSettings.framesToSettle}): one, or with TAA one of
     * each jitter offset, each blended into the history, so the picture is the mean of them all.
     */
    static void renderSettled(Launch launch) {
        for (int i = launch.engine.settings().get(AntialiasSettings.class).framesToSettle(); i > 0; i--) {
            launch.engine.render();
        }
    }

    /** Renders a few frames with the panel and HUD drawn over them, as {@link WindowLoop} does. */
    private static void renderWithUi(Launch launch) {
        var engine = launch.engine;
        glfwSetWindowSize(launch.gl.window(), engine.width(), engine.height()); // the size Dear ImGui lays out in
        Hud hud = new Hud();
        SettingsPanel panel = new SettingsPanel(engine.settings(), launch.panelHost());
        try (Gui gui = new Gui(launch.gl.window(), panel, hud)) {
            for (int i = 0; i < UI_FRAMES; i++) {
                engine.render();
                engine.drawOver(gui::draw);
                engine.collectFrames(true, hud::add);
            }
        }
    }

    /**
     * The picture as the window shows it: its colours, fully opaque. The scene target's alpha is no coverage but
     * whatever the passes left there, and the paper's stencil water (section 3.3) leaves its reflectivity, the
     * blend's destination alpha, over the lake: written as it is, a PNG viewer would show the page through the water.
     */
    static Image opaque(Image image) {
        byte[] rgba = new byte[image.width() * image.height() * 4];
        for (int y = 0, i = 0; y < image.height(); y++) {
            for (int x = 0; x < image.width(); x++, i += 4) {
                for (int c = 0; c < 3; c++) {
                    rgba[i + c] = (byte) image.channel(x, y, c);
                }
                rgba[i + 3] = (byte) 0xFF;
            }
        }
        return new Image(image.width(), image.height(), rgba);
    }
}

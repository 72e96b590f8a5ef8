package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.glfw.GLFW.glfwSetWindowSize;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.openworld.engine.Engine;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.gl.Image;
import picocli.CommandLine;

/**
 * The panel, HUD and controls drawn by Dear ImGui over a real picture, headless: each shows where it should and
 * nowhere else, and hidden leaves the picture as it was.
 */
@Tag("gl")
class GuiRenderTest {

    private static final int W = 640;
    private static final int H = 360;

    private static Launch launch;
    private static Gui gui;
    private static Image plain;

    @BeforeAll
    static void start() {
        RenderOptions options = CommandLine.populateCommand(new RenderOptions(), "--size", W + "x" + H, "--time",
                "16:30", "--set", "terrain.world=tile", "--set", "terrain.size=256", "--set",
                "shadow.resolution=256", "--set", "antialias.method=off"); // TAA jitters each frame: not one picture
        launch = Launch.startWithGui(options, false, "gui test");
        launch.engine.world().resource(Camera.class).setPose(DemoScene.DEFAULT_POSE);
        glfwSetWindowSize(launch.gl.window(), W, H); // the display size Dear ImGui lays out in
        Engine engine = launch.engine;
        Hud hud = new Hud();
        SettingsPanel panel = new SettingsPanel(engine.settings(), launch.panelHost());
        gui = new Gui(launch.gl.window(), panel, hud);
        engine.update();
        engine.render();
        engine.collectFrames(true, hud::add);
        plain = engine.readImage();
    }

    @AfterAll
    static void stop() {
        gui.close();
        launch.close();
    }

    /** The picture with the layer drawn over it, after a few frames (auto-sized windows settle in the second). */
    private static Image withGui() {
        for (int i = 0; i < 3; i++) {
            launch.engine.render();
            launch.engine.drawOver(gui::draw);
        }
        return launch.engine.readImage();
    }

    /** Share of the pixels of a rectangle that differ from the plain picture. */
    private static double changed(Image image, int x0, int y0, int x1, int y1) {
        int changed = 0;
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                for (int c = 0; c < 3; c++) {
                    if (Math.abs(image.channel(x, y, c) - plain.channel(x, y, c)) > 2) {
                        changed++;
                        break;
                    }
                }
            }
        }
        return (double) changed / ((x1 - x0) * (y1 - y0));
    }

    @Test
    void panelHudAndControlsEachShowWhereTheyShould() {
        // default: the panel at the top left, the HUD at the top right
        Image both = withGui();
        assertEquals(W, both.width());
        double panel = changed(both, 20, 40, 150, 200);
        double hud = changed(both, W - 60, 15, W - 15, 40);
        // shares of pixels changed: the panel is an opaque box over most of its region (over half); the HUD's and the
        // controls' text changes a smaller share of theirs (glyphs on a band: over 20–30 %); luma 60 of 255 is a drawn
        // sky, not black
        assertTrue(panel > 0.5, "the panel covers its corner: " + panel);
        assertTrue(hud > 0.2, "the HUD shows at the top right: " + hud);
        assertEquals(0, changed(both, 0, H - 40, 200, H), "the bottom left stays the world's");
        assertTrue(plain.meanLuma(0, 0, W, H / 3) > 60, "the world's sky is drawn under it");

        gui.togglePanel();
        Image hudOnly = withGui();
        assertEquals(0, changed(hudOnly, 20, 40, 150, 200), "F2 hides the panel");
        assertTrue(changed(hudOnly, W - 60, 15, W - 15, 40) > 0.2);

        gui.toggleHud();
        gui.toggleControls();
        Image controls = withGui();
        assertTrue(changed(controls, W / 2 - 40, H / 2 - 20, W / 2 + 40, H / 2 + 20) > 0.3,
                "F1 shows the controls in the middle");
        assertEquals(0, changed(controls, W - 60, 15, W - 15, 40), "F3 hides the HUD");

        gui.toggleControls();
        assertEquals(0, changed(withGui(), 0, 0, W, H), "all hidden: the picture as it was");
        gui.togglePanel();
        gui.toggleHud();
    }
}

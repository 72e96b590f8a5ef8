package org.openworld.demo;

import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiWindowFlags;
import imgui.gl3.ImGuiImplGl3;
import imgui.glfw.ImGuiImplGlfw;
import imgui.type.ImBoolean;

/**
 * The window's Dear ImGui layer (imgui-java with its GLFW and OpenGL 3 backends): the settings panel (F2), the HUD
 * (F3) and the controls (F1), drawn over the finished picture into whatever framebuffer is bound. The window loop
 * hands it GLFW's events first ({@link #key}, {@link #mouseButton}, ...) and leaves to it what it wants: typing into
 * a field does not fly the camera.
 */
final class Gui implements AutoCloseable {

    /** GLSL version line of the OpenGL 3 backend's shaders: the 3.3 core floor of the engine. */
    private static final String GLSL_VERSION = "#version 330 core";

    private final ImGuiImplGlfw platform = new ImGuiImplGlfw();
    private final ImGuiImplGl3 renderer = new ImGuiImplGl3();
    private final SettingsPanel panel;
    private final Hud hud;
    private final ImBoolean showPanel = new ImBoolean(true);
    private final ImBoolean showHud = new ImBoolean(true);
    private final ImBoolean showControls = new ImBoolean(false);

    /**
     * Starts Dear ImGui on the current GL context.
     *
     * @param window the GLFW window whose size, cursor and clipboard the platform backend reads
     */
    Gui(long window, SettingsPanel panel, Hud hud) {
        this.panel = panel;
        this.hud = hud;
        ImGui.createContext();
        ImGui.getIO().setIniFilename(null); // no imgui.ini left in the user's working directory
        platform.init(window, false);
        renderer.init(GLSL_VERSION);
    }

    /** F1, F2, F3: the controls, the panel, the HUD on or off. */
    void toggleControls() {
        showControls.set(!showControls.get());
    }

    void togglePanel() {
        showPanel.set(!showPanel.get());
    }

    void toggleHud() {
        showHud.set(!showHud.get());
    }

    /** Whether a widget has the keyboard (a text field being typed into): the loop then ignores the key. */
    boolean wantsKeyboard() {
        return ImGui.getIO().getWantCaptureKeyboard();
    }

    /** Whether the mouse is over a window of the layer: the loop then does not start mouse look. */
    boolean wantsMouse() {
        return ImGui.getIO().getWantCaptureMouse();
    }

    void key(long window, int key, int scancode, int action, int mods) {
        platform.keyCallback(window, key, scancode, action, mods);
    }

    void character(long window, int codepoint) {
        platform.charCallback(window, codepoint);
    }

    void mouseButton(long window, int button, int action, int mods) {
        platform.mouseButtonCallback(window, button, action, mods);
    }

    void scroll(long window, double dx, double dy) {
        platform.scrollCallback(window, dx, dy);
    }

    /** Builds this frame's windows and draws them into the bound framebuffer. */
    void draw() {
        platform.newFrame();
        ImGui.newFrame();
        if (showPanel.get()) {
            panel.draw();
        }
        if (showHud.get()) {
            hud.draw();
        }
        if (showControls.get()) {
            drawControls();
        }
        ImGui.render();
        renderer.renderDrawData(ImGui.getDrawData());
    }

    private void drawControls() {
        ImGui.setNextWindowPos(ImGui.getIO().getDisplaySizeX() / 2, ImGui.getIO().getDisplaySizeY() / 2,
                ImGuiCond.Appearing, 0.5f, 0.5f);
        if (ImGui.begin("Controls (F1)", showControls, ImGuiWindowFlags.AlwaysAutoResize)) {
            ImGui.text(WindowLoop.CONTROLS);
        }
        ImGui.end();
    }

    @Override
    public void close() {
        renderer.dispose();
        platform.dispose();
        ImGui.destroyContext();
    }
}

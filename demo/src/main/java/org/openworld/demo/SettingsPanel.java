package org.openworld.demo;

import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiDataType;
import imgui.flag.ImGuiInputTextFlags;
import imgui.flag.ImGuiSliderFlags;
import imgui.flag.ImGuiTreeNodeFlags;
import imgui.type.ImFloat;
import imgui.type.ImInt;
import imgui.type.ImString;
import java.io.IOException;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Supplier;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsException;
import org.openworld.engine.settings.SettingsFile;

/**
 * The in-app settings panel (Dear ImGui): the clock and the day's speed, then every setting, one row per
 * {@link PanelEntry}, filed under its group, every change applied at once through {@link Settings#set}. Settings read
 * only when the world is built are marked {@code *}; once one differs from what the world was built with, the panel
 * offers "Rebuild world". "Save" writes every setting to a file that {@code --config} reads; "Load" reads one.
 * "preset" chooses one of {@link Presets}, rebuilding the world if it changed a setting read at start.
 */
final class SettingsPanel {

    /** What the panel asks of the window it lives in. */
    interface Host {
        TimeOfDay time();

        void setTime(TimeOfDay time);

        /** Builds the world again from the current settings, keeping the camera and the clock. */
        void rebuild();
    }

    /** Default file of "Save" and "Load", in the working directory. */
    static final String DEFAULT_FILE = "openworld.settings";
    /** Width of the panel, pixels at font scale 1. */
    private static final float WIDTH_PX = 420;
    /** Room the labels take beside a row's widget, pixels. */
    private static final float LABEL_PX = 170;
    /** Longest text a text field takes, characters. */
    private static final int FIELD_CHARS = 512;
    /** Error red, RGBA. */
    private static final float[] RED = {1f, 0.45f, 0.4f, 1f};

    private final Settings settings;
    private final Host host;
    private final List<PanelEntry> entries;
    /** Each preset's values of the preset keys (read once: the files do not change while the window runs). */
    private final Map<String, Map<String, String>> presets;
    /** The values of the at-start keys the world was built with. */
    private Map<String, String> builtWith;
    private final ImString file = new ImString(DEFAULT_FILE, FIELD_CHARS);
    private final Map<String, ImString> fields = new HashMap<>();
    /** The key of the text field being typed into, if any. */
    private String editing;
    private final float[] slider = new float[1];
    private final ImFloat number = new ImFloat();
    private final ImInt choice = new ImInt();
    private String message = "";
    private boolean rebuildAsked;
    private boolean messageIsError;

    SettingsPanel(Settings settings, Host host) {
        this.settings = settings;
        this.host = host;
        this.entries = PanelEntry.all(settings);
        this.presets = Presets.all(settings);
        worldBuilt();
    }

    /** The rows, in order (tests check every key has one). */
    List<PanelEntry> entries() {
        return entries;
    }

    /** Records the at-start values the world now has (called after a rebuild). */
    void worldBuilt() {
        builtWith = atStartValues();
    }

    /** Whether some at-start setting differs from what the world was built with. */
    boolean needsRebuild() {
        return !atStartValues().equals(builtWith);
    }

    private Map<String, String> atStartValues() {
        Map<String, String> values = new LinkedHashMap<>();
        entries.stream().filter(PanelEntry::atStart).forEach(e -> values.put(e.key(), settings.text(e.key())));
        return values;
    }

    /** Draws the panel; call between {@code ImGui.newFrame} and {@code ImGui.render}. */
    void draw() {
        ImGui.setNextWindowPos(10, 10, ImGuiCond.FirstUseEver);
        ImGui.setNextWindowSize(WIDTH_PX, ImGui.getIO().getDisplaySizeY() * 0.8f, ImGuiCond.FirstUseEver);
        if (ImGui.begin("Settings (F2)")) {
            ImGui.pushItemWidth(-LABEL_PX);
            drawClock();
            drawFileButtons();
            drawPresets();
            if (needsRebuild()) {
                ImGui.separator();
                if (ImGui.button("Rebuild world (applies the * settings)")) {
                    askRebuild();
                }
            }
            if (!message.isEmpty()) {
                if (messageIsError) {
                    ImGui.textColored(RED[0], RED[1], RED[2], RED[3], message);
                } else {
                    ImGui.textWrapped(message);
                }
            }
            drawEntries();
            ImGui.popItemWidth();
        }
        ImGui.end();
    }

    private void drawClock() {
        TimeOfDay t = host.time();
        slider[0] = (float) t.hours();
        if (ImGui.sliderFloat("time of day", slider, 0, 24, DayCycle.describe(t))) {
            host.setTime(new TimeOfDay(slider[0] % 24, t.daySpeed()));
        }
        number.set((float) t.daySpeed());
        if (ImGui.sliderScalar("day speed", ImGuiDataType.Float, number, 0, (float) DayCycle.MAX_SPEED, "x%.0f",
                ImGuiSliderFlags.Logarithmic)) {
            host.setTime(new TimeOfDay(host.time().hours(), number.get()));
        }
        tooltip(() -> "simulated hours per real hour; 0 stops the sun (keys: T pause, [ ] scrub, - = speed)");
    }

    private void drawFileButtons() {
        if (ImGui.button("Save")) {
            file().ifPresent(this::save);
        }
        ImGui.sameLine();
        if (ImGui.button("Load")) {
            file().ifPresent(this::load);
        }
        ImGui.sameLine();
        ImGui.inputText("file", file);
        tooltip(() -> "a file of key=value lines: 'openworld --config FILE' starts with it");
    }

    /** The preset the settings match now, or "custom"; choosing one applies it. */
    private void drawPresets() {
        String current = Presets.matching(presets, settings).orElse("custom");
        if (ImGui.beginCombo("preset", current)) {
            for (String name : presets.keySet()) {
                if (ImGui.selectable(name, name.equals(current))) {
                    choosePreset(name);
                }
            }
            ImGui.endCombo();
        }
        tooltip(() -> "low, default, ultra or the paper's method, paper (assets/presets/NAME.settings); "
                + "'openworld --preset NAME' starts with it");
    }

    /**
     * Applies a preset's values ({@link Presets#apply}: its keys only, the world's own settings kept) and rebuilds the
     * world if that changed a setting read at start.
     */
    void choosePreset(String name) {
        Presets.apply(name, settings);
        boolean rebuild = needsRebuild();
        if (rebuild) {
            askRebuild();
        }
        say("preset " + name + (rebuild ? "; the world is rebuilt with it" : ""), false);
    }

    /** What "Rebuild world" does: asks the window to rebuild before its next frame. */
    void askRebuild() {
        rebuildAsked = true;
    }

    /**
     * Builds the world again if "Rebuild world" was pressed: called by the window between frames, not while the
     * panel draws into the old world's picture. A failure (an import file that is not there) leaves the old world
     * and is shown.
     */
    void rebuildIfAsked() {
        if (!rebuildAsked) {
            return;
        }
        rebuildAsked = false;
        long start = System.nanoTime();
        try {
            host.rebuild();
            worldBuilt();
            say(String.format("world rebuilt in %.1f s", (System.nanoTime() - start) / 1e9), false);
        } catch (RuntimeException e) {
            say("the world could not be rebuilt, the old one stays: " + e.getMessage(), true);
        }
    }

    /** The file named in the field, or empty with the reason shown. */
    private Optional<Path> file() {
        try {
            return Optional.of(Path.of(file.get().strip()));
        } catch (InvalidPathException e) {
            say("'" + file.get() + "' is not a file name: " + e.getReason(), true);
            return Optional.empty();
        }
    }

    /** Writes every setting to the file. */
    void save(Path path) {
        try {
            SettingsFile.write(settings, path);
            say("saved " + path.toAbsolutePath() + "; start with it: openworld --config " + path, false);
        } catch (IOException e) {
            say("could not save " + path + ": " + e.getMessage(), true);
        }
    }

    /**
     * Reads the file into fresh settings, as {@code --config} does (keys it does not name go back to their defaults),
     * and only then takes them over, so a bad file changes nothing.
     */
    void load(Path path) {
        try {
            Settings loaded = settings.defaults();
            SettingsFile.read(path, loaded);
            settings.takeOver(loaded);
            say("loaded " + path + (needsRebuild() ? "; some * settings differ: rebuild the world to apply them" : ""),
                    false);
        } catch (SettingsException e) {
            say(e.getMessage(), true);
        }
    }

    private void drawEntries() {
        String group = null;
        boolean open = false;
        for (PanelEntry e : entries) {
            if (!e.group().equals(group)) {
                group = e.group();
                open = ImGui.collapsingHeader(group.equals("system") ? "systems" : group,
                        group.equals("system") ? ImGuiTreeNodeFlags.DefaultOpen : 0);
            }
            if (open) {
                ImGui.pushID(e.key());
                drawEntry(e);
                ImGui.popID();
            }
        }
    }

    private void drawEntry(PanelEntry e) {
        String label = e.label() + (e.atStart() ? " *" : "") + (e.unit().isEmpty() ? "" : " (" + e.unit() + ")");
        String current = settings.text(e.key());
        switch (e.widget()) {
            case CHECKBOX -> {
                if (ImGui.checkbox(label, current.equals("on"))) {
                    apply(e, current.equals("on") ? "off" : "on");
                }
            }
            case CHOICE -> {
                choice.set(e.choices().indexOf(current));
                if (ImGui.combo(label, choice, e.choices().toArray(String[]::new))) {
                    apply(e, e.choices().get(choice.get()));
                }
            }
            case INT_SLIDER, SLIDER, LOG_SLIDER -> {
                slider[0] = Float.parseFloat(current);
                boolean integer = e.widget() == PanelEntry.Widget.INT_SLIDER;
                int flags = ImGuiSliderFlags.AlwaysClamp
                        | (e.widget() == PanelEntry.Widget.LOG_SLIDER ? ImGuiSliderFlags.Logarithmic : 0);
                if (ImGui.sliderFloat(label, slider, (float) e.min(), (float) e.max(), integer ? "%.0f" : "%.4g",
                        flags)) {
                    apply(e, e.text(slider[0]));
                }
            }
            case FIELD -> {
                // typed text stays while the field is being edited; otherwise the field shows the current value
                ImString text = fields.computeIfAbsent(e.key(), k -> new ImString(FIELD_CHARS));
                if (!e.key().equals(editing) && !text.get().equals(current)) {
                    text.set(current);
                }
                boolean entered = ImGui.inputText(label, text, ImGuiInputTextFlags.EnterReturnsTrue);
                if (ImGui.isItemActive()) {
                    editing = e.key();
                } else if (e.key().equals(editing)) {
                    editing = null;
                }
                if (entered) {
                    apply(e, text.get().strip());
                }
            }
        }
        tooltip(() -> e.doc() + (e.atStart() ? "; read when the world is built" : "") + "\n--set " + e.key() + "="
                + settings.text(e.key()));
    }

    private void apply(PanelEntry e, String text) {
        try {
            settings.set(e.key(), text);
            if (message.startsWith(e.key())) {
                say("", false);
            }
        } catch (SettingsException ex) {
            say(ex.getMessage(), true);
        }
    }

    private void say(String text, boolean error) {
        message = text;
        messageIsError = error;
    }

    /** The last item's tooltip; its text is made only while the item is hovered, not for every row every frame. */
    private static void tooltip(Supplier<String> text) {
        if (ImGui.isItemHovered()) {
            ImGui.beginTooltip();
            ImGui.text(text.get());
            ImGui.endTooltip();
        }
    }
}

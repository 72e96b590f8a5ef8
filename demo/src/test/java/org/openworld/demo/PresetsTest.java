package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.Engine;
import org.openworld.engine.settings.Settings;
import picocli.CommandLine;

/** The presets (the quality levels and the paper's): their files, what choosing one does, and the order of --preset, --config and --set. */
class PresetsTest {

    private static final Path FOLDER = Path.of("../assets/presets");

    @TempDir
    Path dir;

    private static Settings demoSettings() {
        return Engine.settingsFor(DemoScene.systems());
    }

    private static RenderOptions options(String... args) {
        SettingsCommand command = new SettingsCommand();
        new CommandLine(command).parseArgs(args);
        return command.render;
    }

    @Test
    void everyPresetFileLoadsEveryLineIsAValidKeyAndNoKeyRepeats() throws IOException {
        List<String> files;
        try (Stream<Path> list = Files.list(FOLDER)) {
            files = list.map(p -> p.getFileName().toString()).sorted().toList();
        }
        assertEquals(Presets.NAMES.stream().map(n -> n + ".settings").sorted().toList(), files,
                "a file for each preset, and no other");
        for (String name : Presets.NAMES) {
            Settings settings = demoSettings();
            Presets.apply(name, settings); // a bad line throws, naming the file and line
            List<String> keys = new ArrayList<>();
            for (String line : Files.readAllLines(FOLDER.resolve(name + ".settings"))) {
                if (!line.isBlank() && !line.startsWith("#")) {
                    String key = line.substring(0, line.indexOf('=')).strip();
                    assertTrue(settings.keys().contains(key), () -> name + ": " + key + " is no setting");
                    assertFalse(keys.contains(key), () -> name + ": " + key + " twice");
                    keys.add(key);
                    Settings alone = demoSettings();
                    alone.apply(line);
                    assertEquals(alone.text(key), settings.text(key), () -> name + ": " + line);
                }
            }
        }
    }

    @Test
    void defaultIsTheDefaultsAndTheOthersDifferFromIt() {
        Settings defaults = demoSettings();
        Settings chosen = demoSettings();
        Presets.apply("default", chosen);
        assertEquals(defaults.asExactText(), chosen.asExactText());
        assertFalse(Presets.keys(defaults).isEmpty());
        assertEquals("full", Presets.values("ultra", defaults).get("water.reflection"));
        assertEquals("off", Presets.values("low", defaults).get("system.shadow"));
    }

    @Test
    void choosingAPresetResetsThePresetKeysAndKeepsTheWorld() {
        Settings settings = demoSettings();
        settings.set("engine.seed", "7");
        settings.set("terrain.relief", "1200");
        Presets.apply("low", settings);
        Presets.apply("ultra", settings);
        Map<String, Map<String, String>> all = Presets.all(settings);
        assertEquals(Optional.of("ultra"), Presets.matching(all, settings));
        assertEquals("on", settings.text("system.shadow"), "low's key back to its default under ultra");
        Presets.apply("default", settings);
        assertEquals(Optional.of("default"), Presets.matching(all, settings));
        assertEquals("7", settings.text("engine.seed"));
        assertEquals("1200", settings.text("terrain.relief"));
        settings.set("water.reflection", "full");
        assertEquals(Optional.empty(), Presets.matching(all, settings), "custom");
    }

    @Test
    void thePaperPresetPutsEachSystemOnThePapersMethodAndLeavingItUndoesAll() {
        Settings defaults = demoSettings();
        Settings settings = demoSettings();
        settings.set("engine.seed", "7");
        Presets.apply("paper", settings);
        Map<String, String> paper = Map.of("terrain.beta", "1", "terrain.snow-base", "0", "terrain.snow-full", "1",
                "materials.detail-scale", "1", "lod.mode", "flat-grid", "lod.rule", "paper", "atmosphere.scattering",
                "single", "atmosphere.wavelengths", "6", "shadow.depth", "fixed24", "water.method", "stencil");
        paper.forEach((key, value) -> assertEquals(value, settings.text(key), key));
        assertEquals("7", settings.text("engine.seed"), "the seed is the world's, not the preset's");
        Map<String, Map<String, String>> all = Presets.all(settings);
        assertEquals(Optional.of("paper"), Presets.matching(all, settings));

        Presets.apply("low", settings);
        assertEquals("2.2", settings.text("terrain.beta"), "a quality preset leaves the paper's method");
        assertEquals("off", settings.text("system.shadow"));
        Presets.apply("default", settings);
        settings.set("engine.seed", "1");
        assertEquals(defaults.asExactText(), settings.asExactText(), "default undoes all of paper and low");
    }

    @Test
    void thePresetComesFirstThenTheConfigFileThenSeedAndSet() throws IOException {
        assertEquals("full", Launch.settings(options("--preset", "ultra")).text("water.reflection"));
        assertEquals("half", Launch.settings(options("--preset", "ultra", "--set", "water.reflection=half"))
                .text("water.reflection"));
        Path config = dir.resolve("my.settings");
        Files.writeString(config, "shadow.resolution=512\nwater.reflection=half\n");
        Settings s = Launch.settings(options("--config", config.toString(), "--preset", "ultra", "--set",
                "shadow.resolution=1024"));
        assertEquals("half", s.text("water.reflection"), "the config file wins over the preset");
        assertEquals("1024", s.text("shadow.resolution"), "--set wins over both");
        assertEquals("5", s.text("shadow.kernel"), "the preset's other keys stay");
    }

    @Test
    void anUnknownPresetNamesTheValidOnes() {
        UserError e = assertThrows(UserError.class, () -> Launch.settings(options("--preset", "Ultra")));
        assertEquals("unknown preset 'Ultra': expected one of low, default, ultra, paper", e.getMessage());
    }
}

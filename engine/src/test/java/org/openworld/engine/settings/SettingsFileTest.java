package org.openworld.engine.settings;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.settings.SettingsTest.OtherSettings;
import org.openworld.engine.settings.SettingsTest.ProbeSettings;

/** Saving settings to a file and reading them back. */
class SettingsFileTest {

    @TempDir
    Path dir;

    private static Settings fresh() {
        Map<String, Boolean> systems = new LinkedHashMap<>();
        systems.put("water", true);
        systems.put("snow", false);
        return new Settings(List.of(
                SettingsGroup.of("probe", ProbeSettings.class, ProbeSettings.DEFAULTS),
                SettingsGroup.of("other", OtherSettings.class, OtherSettings.DEFAULTS),
                SettingsGroup.of("file", FileSettings.class, FileSettings.DEFAULTS)), systems);
    }

    public record FileSettings(@Setting(doc = "a file to read") String source,
                               @Setting(doc = "a file name, resolved from a settings file's folder", file = true)
                               String map) {
        public static final FileSettings DEFAULTS = new FileSettings("", "");
    }

    @Test
    void aRelativeFileNameInAFileIsReadFromTheFilesFolder() throws IOException {
        Path folder = Files.createDirectories(dir.resolve("world"));
        Path file = Files.writeString(folder.resolve("my.settings"), "file.map=heights/ok257.raw\nfile.source=notes\n");
        Settings s = fresh();
        SettingsFile.read(file, s);
        assertEquals(folder.toAbsolutePath().resolve("heights/ok257.raw").toString(), s.text("file.map"),
                "a file setting: from the settings file's folder");
        assertEquals("notes", s.text("file.source"), "any other text is kept as written");
        Files.writeString(file, "file.map=" + dir.toAbsolutePath().resolve("abs.raw") + "\n");
        SettingsFile.read(file, s);
        assertEquals(dir.toAbsolutePath().resolve("abs.raw").toString(), s.text("file.map"), "an absolute name as is");
        s.set("file.map", "here.raw");
        assertEquals("here.raw", s.text("file.map"), "--set keeps the current folder's meaning");
    }

    @Test
    void savedAndLoadedGivesTheSameSettings() throws IOException {
        Settings saved = fresh();
        saved.set("probe.radius", "12.345678912345");
        saved.set("probe.sample-count", "0");
        saved.set("probe.water-mode", "planar-reflection");
        saved.set("probe.shadows-enabled", "off");
        saved.set("other.lod-bias", "-1.75");
        saved.set("file.source", "maps/peak #2.png");
        saved.set("system.water", "off");
        saved.set("system.snow", "on");
        Path file = dir.resolve("nested/my.settings");

        SettingsFile.write(saved, file);
        Settings loaded = fresh();
        SettingsFile.read(file, loaded);

        assertNotEquals(fresh().asText(), saved.asText(), "the test changes every kind of key");
        assertEquals(saved.asExactText(), loaded.asExactText());
        assertEquals(saved.get(ProbeSettings.class), loaded.get(ProbeSettings.class));
        assertEquals(saved.get(FileSettings.class), loaded.get(FileSettings.class));
        assertTrue(!loaded.systemEnabled("water") && loaded.systemEnabled("snow"));
    }

    /** Found by the fuzz test: a text value with a line break was taken, then saved as two lines that do not read. */
    @Test
    void aTextValueWithALineBreakIsRefusedSoEverySavedFileReadsBack() {
        Settings s = fresh();
        for (String value : new String[] {"a\nb", "a\rb", "a\r\nb"}) {
            SettingsException e = assertThrows(SettingsException.class, () -> s.set("file.source", value));
            assertEquals("file.source is not valid: expected one line of text, found a line break", e.getMessage());
        }
        assertEquals("", s.text("file.source"));
    }

    @Test
    void aHandWrittenFileMayHoldAFewKeysCommentsAndBlankLines() throws IOException {
        Path file = dir.resolve("few.settings");
        Files.writeString(file, "# my favourite probe\n\n  probe.radius = 20  \nsystem.snow=on\n");
        Settings s = fresh();

        SettingsFile.read(file, s);

        assertEquals(20, s.get(ProbeSettings.class).radius());
        assertTrue(s.systemEnabled("snow"));
        assertEquals(ProbeSettings.DEFAULTS.sampleCount(), s.get(ProbeSettings.class).sampleCount());
    }

    @Test
    void aBadLineNamesTheFileTheLineAndTheKey() throws IOException {
        Path file = dir.resolve("bad.settings");
        Files.writeString(file, "probe.radius=20\n# fine so far\nprobe.radius=5000\nother.lod-bias=1\n");
        Settings s = fresh();

        SettingsException e = assertThrows(SettingsException.class, () -> SettingsFile.read(file, s));

        assertTrue(e.getMessage().startsWith(file + ":3: probe.radius=5000"), e.getMessage());
        assertTrue(e.getMessage().contains("1 .. 100"), e.getMessage());
        assertEquals(0, s.get(OtherSettings.class).lodBias(), "nothing after the bad line is applied");
    }

    @Test
    void readIntoDefaultsAndTakenOverReplacesEveryValue() throws IOException {
        Settings live = fresh();
        live.set("other.lod-bias", "1.5");
        live.set("system.water", "off");
        Path file = dir.resolve("radius.settings");
        Files.writeString(file, "probe.radius=30\n");

        Settings loaded = live.defaults();
        SettingsFile.read(file, loaded);
        live.takeOver(loaded);

        assertEquals(30, live.get(ProbeSettings.class).radius());
        assertEquals(0, live.get(OtherSettings.class).lodBias(), "a key the file does not name is at its default");
        assertTrue(live.systemEnabled("water") && !live.systemEnabled("snow"), "switches too");
        assertThrows(IllegalArgumentException.class, () -> live.takeOver(new Settings(List.of())));
    }

    @Test
    void aMissingFileIsNamed() {
        Path file = dir.resolve("nowhere.settings");

        SettingsException e = assertThrows(SettingsException.class, () -> SettingsFile.read(file, fresh()));

        assertTrue(e.getMessage().contains(file.toString()) && e.getMessage().contains("does not exist"),
                e.getMessage());
    }
}

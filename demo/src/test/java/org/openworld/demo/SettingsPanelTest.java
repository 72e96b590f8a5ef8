package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.Engine;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.settings.Settings;

/** The settings panel's rows, saving, loading and rebuilding, without drawing (GuiRenderTest draws it). */
class SettingsPanelTest {

    @TempDir
    Path dir;

    private int rebuilds;

    private final SettingsPanel.Host host = new SettingsPanel.Host() {
        private TimeOfDay time = new TimeOfDay(10, 0);

        @Override
        public TimeOfDay time() {
            return time;
        }

        @Override
        public void setTime(TimeOfDay t) {
            time = t;
        }

        @Override
        public void rebuild() {
            rebuilds++;
        }
    };

    private static Settings demoSettings() {
        return Engine.settingsFor(DemoScene.systems());
    }

    @Test
    void everySetKeyHasExactlyOnePanelRow() {
        Settings settings = demoSettings();
        List<String> rows = new SettingsPanel(settings, host).entries().stream().map(PanelEntry::key).toList();

        assertEquals(settings.keys(), rows, "the same keys, in the same order, once each");
        assertTrue(rows.containsAll(List.of("system.terrain", "system.particles", "shadow.kernel", "water.alpha",
                "atmosphere.wavelengths", "clouds.mapping", "lod.base-resolution", "particles.count")), rows.toString());
    }

    @Test
    void eachKindOfSettingGetsTheWidgetThatFitsIt() {
        Map<String, PanelEntry> rows = PanelEntry.all(demoSettings()).stream()
                .collect(Collectors.toMap(PanelEntry::key, Function.identity()));

        assertEquals(PanelEntry.Widget.CHECKBOX, rows.get("system.water").widget());
        assertEquals(PanelEntry.Widget.CHECKBOX, rows.get("materials.normal-map").widget());
        assertEquals(PanelEntry.Widget.CHOICE, rows.get("water.method").widget());
        assertEquals(List.of("fresnel", "stencil"), rows.get("water.method").choices());
        assertEquals(PanelEntry.Widget.INT_SLIDER, rows.get("shadow.kernel").widget());
        assertEquals(PanelEntry.Widget.SLIDER, rows.get("water.alpha").widget());
        assertEquals(PanelEntry.Widget.LOG_SLIDER, rows.get("lod.base-resolution").widget(), "1 m .. 100 km");
        assertEquals(PanelEntry.Widget.FIELD, rows.get("engine.seed").widget(), "two billion values: typed");
        assertEquals(PanelEntry.Widget.FIELD, rows.get("terrain.import-file").widget());
        assertTrue(rows.get("terrain.relief").atStart() && !rows.get("water.alpha").atStart());
        assertEquals("shadow", rows.get("shadow.kernel").group());
        assertEquals("kernel", rows.get("shadow.kernel").label());
    }

    @Test
    void aSliderValueIsTextTheSettingTakes() {
        Settings settings = demoSettings();
        Map<String, PanelEntry> rows = PanelEntry.all(settings).stream()
                .collect(Collectors.toMap(PanelEntry::key, Function.identity()));

        settings.set("shadow.kernel", rows.get("shadow.kernel").text(5.0f));
        settings.set("water.alpha", rows.get("water.alpha").text(0.3f));

        assertEquals("5", settings.text("shadow.kernel"));
        assertEquals("0.3", settings.text("water.alpha"), "no float noise such as 0.30000001");
    }

    @Test
    void savedSettingsLoadBackTheSameAndABadFileChangesNothing() throws Exception {
        Settings settings = demoSettings();
        SettingsPanel panel = new SettingsPanel(settings, host);
        settings.set("system.water", "off");
        settings.set("shadow.kernel", "7");
        settings.set("clouds.mapping", "spherical");
        settings.set("sky.exposure", "1.2345678");
        Map<String, String> saved = settings.asExactText();
        Path file = dir.resolve("panel.settings");

        panel.save(file);
        settings.set("shadow.kernel", "1");
        settings.set("system.water", "on");
        settings.set("particles.count", "5");
        panel.load(file);

        assertEquals(saved, settings.asExactText());
        assertNotEquals(demoSettings().asExactText(), saved);

        Files.writeString(file, "shadow.kernel=3\nwater.alpha=7\n");
        panel.load(file);
        assertEquals(saved, settings.asExactText(), "a bad line: nothing of the file is taken");
    }

    @Test
    void changingASettingReadAtStartOffersARebuildAndPressingItRebuildsOnce() {
        Settings settings = demoSettings();
        SettingsPanel panel = new SettingsPanel(settings, host);
        settings.set("water.alpha", "0.9");
        assertFalse(panel.needsRebuild(), "read every frame: applies at once");

        settings.set("terrain.relief", "1200");
        assertTrue(panel.needsRebuild());
        panel.rebuildIfAsked();
        assertEquals(0, rebuilds, "nothing until the button is pressed");

        panel.askRebuild();
        panel.rebuildIfAsked();
        panel.rebuildIfAsked();
        assertEquals(1, rebuilds);
        assertFalse(panel.needsRebuild(), "the world now has the new relief");
    }

    @Test
    void choosingAPresetAppliesItAndRebuildsOnlyIfASettingReadAtStartChanged() {
        Settings settings = demoSettings();
        SettingsPanel panel = new SettingsPanel(settings, host);
        panel.choosePreset("ultra");
        assertEquals("full", settings.text("water.reflection"));
        panel.rebuildIfAsked();
        assertEquals(1, rebuilds, "ultra's triplanar cliffs (materials.cliffs) are compiled in at start");

        panel.choosePreset("ultra");
        panel.rebuildIfAsked();
        assertEquals(1, rebuilds, "the same preset again changes nothing");

        panel.choosePreset("low");
        assertEquals("64", settings.text("clouds.resolution"));
        assertEquals("half", settings.text("water.reflection"), "ultra's keys back to their defaults");
        panel.rebuildIfAsked();
        assertEquals(2, rebuilds, "low's cloud field (clouds.resolution, clouds.frames) is made at start");
        assertFalse(panel.needsRebuild());
    }
}

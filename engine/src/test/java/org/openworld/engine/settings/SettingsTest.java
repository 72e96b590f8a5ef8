package org.openworld.engine.settings;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** Keys, parsing, errors and text round trips of the settings, over a small record made for the test. */
class SettingsTest {

    public enum WaterMode { FLAT, SCREEN_SPACE, PLANAR_REFLECTION }

    /** A settings record like a system's: every kind of component, and a rule across two of them. */
    public record ProbeSettings(
            @Setting(doc = "probe radius", unit = "m", min = 1, max = 100) double radius,
            @Setting(doc = "samples per probe", min = 0, max = 64) int sampleCount,
            @Setting(doc = "whether probes cast shadows") boolean shadowsEnabled,
            @Setting(doc = "how water is drawn") WaterMode waterMode,
            @Setting(doc = "blend weight, unbounded") double blendWeight) {

        public ProbeSettings {
            if (sampleCount > radius) {
                throw new IllegalArgumentException("sample count " + sampleCount + " exceeds radius " + radius);
            }
        }

        public static final ProbeSettings DEFAULTS = new ProbeSettings(10, 8, true, WaterMode.FLAT, 0.5);
    }

    public record OtherSettings(@Setting(doc = "level of detail bias", min = -2, max = 2) double lodBias) {
        public static final OtherSettings DEFAULTS = new OtherSettings(0);
    }

    static Settings settings() {
        return new Settings(List.of(
                SettingsGroup.of("probe", ProbeSettings.class, ProbeSettings.DEFAULTS),
                SettingsGroup.of("other", OtherSettings.class, OtherSettings.DEFAULTS)));
    }

    @Test
    void keysAreThePrefixAndTheComponentsInKebabCase() {
        assertEquals(List.of("probe.radius", "probe.sample-count", "probe.shadows-enabled", "probe.water-mode",
                "probe.blend-weight", "other.lod-bias"), settings().keys());
    }

    @Test
    void theChangeCountGrowsWithEverySetAndNotWithReads() {
        Settings s = new Settings(List.of(SettingsGroup.of("probe", ProbeSettings.class, ProbeSettings.DEFAULTS)),
                java.util.Map.of("water", true));
        long start = s.changes();
        s.get(ProbeSettings.class);
        s.text("probe.radius");
        assertEquals(start, s.changes(), "reading changes nothing");
        s.set("probe.radius", "42.5");
        assertEquals(start + 1, s.changes(), "a group's value");
        s.set("system.water", "off");
        assertEquals(start + 2, s.changes(), "a system switch");
        s.takeOver(s.defaults());
        assertEquals(start + 3, s.changes(), "every value at once");
        assertThrows(SettingsException.class, () -> s.set("probe.radius", "1000"));
        assertEquals(start + 3, s.changes(), "a refused value sets nothing");
    }

    @Test
    void startsAtTheDefaults() {
        assertEquals(ProbeSettings.DEFAULTS, settings().get(ProbeSettings.class));
    }

    @Test
    void setAndApplyParseEveryKind() {
        Settings s = settings();

        s.set("probe.radius", "42.5");
        s.apply("probe.sample-count = 12");
        s.set("probe.shadows-enabled", "off");
        s.apply("probe.water-mode=screen-space");
        s.set("probe.blend-weight", "-3.25");
        s.set("other.lod-bias", "-1.5");

        assertEquals(new ProbeSettings(42.5, 12, false, WaterMode.SCREEN_SPACE, -3.25), s.get(ProbeSettings.class));
        assertEquals(new OtherSettings(-1.5), s.get(OtherSettings.class));
        s.set("probe.shadows-enabled", "on");
        assertTrue(s.get(ProbeSettings.class).shadowsEnabled());
    }

    @Test
    void outOfRangeNamesTheKeyAndTheValidRange() {
        Settings s = settings();

        SettingsException e = assertThrows(SettingsException.class, () -> s.set("probe.radius", "500"));
        SettingsException i = assertThrows(SettingsException.class, () -> s.set("probe.sample-count", "-1"));

        assertTrue(e.getMessage().contains("probe.radius"), e.getMessage());
        assertTrue(e.getMessage().contains("1 .. 100"), e.getMessage());
        assertTrue(e.getMessage().contains(" m"), e.getMessage());
        assertTrue(i.getMessage().contains("probe.sample-count"), i.getMessage());
        assertTrue(i.getMessage().contains("0 .. 64"), i.getMessage());
        assertEquals(ProbeSettings.DEFAULTS, s.get(ProbeSettings.class), "a rejected value changes nothing");
    }

    @Test
    void valuesThatAreNotOfTheKeysTypeNameTheKey() {
        Settings s = settings();

        for (String[] bad : new String[][] {
                {"probe.radius", "ten"}, {"probe.radius", "NaN"}, {"probe.sample-count", "2.5"},
                {"probe.shadows-enabled", "maybe"}, {"probe.water-mode", "ocean"}}) {
            SettingsException e = assertThrows(SettingsException.class, () -> s.set(bad[0], bad[1]), bad[1]);
            assertTrue(e.getMessage().contains(bad[0]), e.getMessage());
            assertTrue(e.getMessage().contains(bad[1]), e.getMessage());
        }
        SettingsException mode = assertThrows(SettingsException.class, () -> s.set("probe.water-mode", "ocean"));
        assertTrue(mode.getMessage().contains("flat|screen-space|planar-reflection"), mode.getMessage());
        SettingsException flag = assertThrows(SettingsException.class, () -> s.set("probe.shadows-enabled", "maybe"));
        assertTrue(flag.getMessage().contains("on|off"), flag.getMessage());
    }

    @Test
    void unknownKeyIsAnErrorWithASuggestion() {
        Settings s = settings();

        SettingsException suggested = assertThrows(SettingsException.class, () -> s.set("radius", "3"));
        SettingsException unknown = assertThrows(SettingsException.class, () -> s.set("sky.turbidity", "3"));

        assertTrue(suggested.getMessage().contains("'radius'"), suggested.getMessage());
        assertTrue(suggested.getMessage().contains("did you mean 'probe.radius'"), suggested.getMessage());
        assertTrue(unknown.getMessage().contains("'sky.turbidity'"), unknown.getMessage());
        assertTrue(!unknown.getMessage().contains("did you mean"), unknown.getMessage());
        assertThrows(SettingsException.class, () -> s.apply("probe.radius"), "no '='");
    }

    @Test
    void recordValidationBecomesASettingsExceptionNamingTheKey() {
        Settings s = settings();

        SettingsException e = assertThrows(SettingsException.class, () -> s.set("probe.sample-count", "20"));

        assertTrue(e.getMessage().startsWith("probe.sample-count: "), e.getMessage());
        assertTrue(e.getMessage().contains("exceeds radius"), e.getMessage());
        assertEquals(ProbeSettings.DEFAULTS, s.get(ProbeSettings.class));
        s.set("probe.radius", "30");
        s.set("probe.sample-count", "20");
        assertEquals(20, s.get(ProbeSettings.class).sampleCount());
    }

    @Test
    void asTextRoundTripsThroughApply() {
        Settings s = settings();
        s.set("probe.radius", "12.375");
        s.set("probe.sample-count", "3");
        s.set("probe.shadows-enabled", "off");
        s.set("probe.water-mode", "planar-reflection");
        s.set("probe.blend-weight", "0.1");
        s.set("other.lod-bias", "1");

        Map<String, String> text = s.asText();
        Settings copy = settings();
        text.forEach((k, v) -> copy.apply(k + "=" + v));

        assertEquals(s.keys(), List.copyOf(text.keySet()));
        assertEquals("off", text.get("probe.shadows-enabled"));
        assertEquals("planar-reflection", text.get("probe.water-mode"));
        assertEquals(s.get(ProbeSettings.class), copy.get(ProbeSettings.class));
        assertEquals(s.get(OtherSettings.class), copy.get(OtherSettings.class));
    }

    @Test
    void describeListsEveryKeyWithItsDocumentation() {
        Settings s = settings();

        String table = s.describe();

        for (String key : s.keys()) {
            assertTrue(table.contains(key), key + " missing from\n" + table);
        }
        assertTrue(table.contains("probe radius"), table);
        assertTrue(table.contains("1 .. 100"), table);
        assertTrue(table.contains("on|off"), table);
        assertTrue(table.contains("any double"), table);
    }

    /** A record component without documentation cannot become a key. */
    public record Undocumented(double size) {
    }

    /** Documented, but not public: its accessors cannot be called from the settings code of another package. */
    record Hidden(@Setting(doc = "size", min = 0, max = 10) double size) {
    }

    @Test
    void groupsRejectUndocumentedComponentsNonPublicRecordsAndDuplicates() {
        assertThrows(IllegalStateException.class, () -> SettingsGroup.of("x", Undocumented.class, new Undocumented(1)));
        IllegalStateException hidden = assertThrows(IllegalStateException.class,
                () -> SettingsGroup.of("hidden", Hidden.class, new Hidden(1)));
        assertTrue(hidden.getMessage().contains("Hidden") && hidden.getMessage().contains("public"), hidden.getMessage());
        SettingsGroup<OtherSettings> other = SettingsGroup.of("other", OtherSettings.class, OtherSettings.DEFAULTS);
        assertThrows(IllegalArgumentException.class, () -> new Settings(List.of(other, other)));
    }

    @Test
    void systemSwitchesAreKeysLikeAnyOther() {
        Settings s = new Settings(List.of(SettingsGroup.of("other", OtherSettings.class, OtherSettings.DEFAULTS)),
                new java.util.LinkedHashMap<>(Map.of("snow", false)));

        assertEquals(List.of("system.snow", "other.lod-bias"), s.keys());
        assertEquals("off", s.text("system.snow"));
        assertTrue(s.hasSystem("snow"));
        assertTrue(!s.systemEnabled("snow"));
        assertTrue(s.systemEnabled("a-system-without-a-switch"));
        s.apply("system.snow=on");
        assertTrue(s.systemEnabled("snow"));
        assertEquals("on", s.asText().get("system.snow"));
        assertTrue(s.describe().lines().anyMatch(l -> l.startsWith("system.snow") && l.contains("off")
                && l.contains("on|off")), s.describe());
        SettingsException e = assertThrows(SettingsException.class, () -> s.set("system.snow", "maybe"));
        assertTrue(e.getMessage().contains("system.snow") && e.getMessage().contains("on|off"), e.getMessage());
    }

    public record Generated(
            @Setting(doc = "samples", min = 1, max = 10, atStart = true) int samples,
            @Setting(doc = "tint", min = 0, max = 1) double tint) {
        public static final Generated DEFAULTS = new Generated(4, 0.5);
    }

    @Test
    void settingsReadAtStartSaySo() {
        Settings s = new Settings(List.of(SettingsGroup.of("gen", Generated.class, Generated.DEFAULTS)));

        String samples = s.describe().lines().filter(l -> l.startsWith("gen.samples")).findFirst().orElseThrow();
        String tint = s.describe().lines().filter(l -> l.startsWith("gen.tint")).findFirst().orElseThrow();

        assertTrue(samples.endsWith(Settings.AT_START_NOTE), samples);
        assertTrue(!tint.contains(Settings.AT_START_NOTE), tint);
    }
}

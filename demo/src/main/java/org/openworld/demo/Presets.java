package org.openworld.demo;

import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsFile;

/**
 * The presets ({@code --preset NAME}, and the settings panel's "preset"): each is a settings file,
 * {@code assets/presets/NAME.settings} on the classpath, in the format {@code --config} reads. Three are quality
 * levels: {@code default} is the defaults (its file names no key), {@code ultra} spends more time on the picture,
 * {@code low} less. The fourth, {@code paper}, is no quality level but the 2017 paper's method in every system
 * (docs/paper.md), to set its pictures beside the default ones ({@code openworld figures --preset paper}).
 *
 * <p>A preset sets the keys that some preset moves off its default, the preset keys, and nothing else: choosing one
 * first puts every preset key back to its default, then applies its file. So going from {@code ultra} or
 * {@code paper} to {@code default} undoes all of it, and the world's seed, size and an imported height map stay what
 * they were (its shape and snow are preset keys, which {@code paper} sets).
 */
final class Presets {

    /** Every preset: the quality levels, cheapest first, then the paper's method. */
    static final List<String> NAMES = List.of("low", "default", "ultra", "paper");

    private Presets() {
    }

    /** The preset's file on the classpath. */
    static String resource(String name) {
        return "assets/presets/" + name + ".settings";
    }

    /**
     * Chooses a preset: every preset key back to its default, then the preset's file applied; every other key kept.
     *
     * @throws UserError naming the valid presets if there is no preset of this name
     */
    static void apply(String name, Settings settings) {
        Map<String, String> values = values(name, settings);
        Settings chosen = settings.defaults();
        chosen.takeOver(settings);
        values.forEach(chosen::set);
        settings.takeOver(chosen);
    }

    /** Every preset's {@link #values}, by name, in the order of {@link #NAMES}. */
    static Map<String, Map<String, String>> all(Settings like) {
        Map<String, Map<String, String>> all = new LinkedHashMap<>();
        NAMES.forEach(name -> all.put(name, values(name, like)));
        return all;
    }

    /**
     * The preset (of {@link #all}) whose values every preset key has now, if any: the panel shows it, or "custom".
     */
    static Optional<String> matching(Map<String, Map<String, String>> presets, Settings settings) {
        Map<String, String> now = settings.asExactText();
        return presets.entrySet().stream().filter(preset -> preset.getValue().entrySet().stream()
                .allMatch(e -> now.get(e.getKey()).equals(e.getValue()))).map(Map.Entry::getKey).findFirst();
    }

    /** Every preset key with its value in the preset {@code name}, in key order. */
    static Map<String, String> values(String name, Settings like) {
        Map<String, String> preset = fileOnDefaults(name, like).asExactText();
        Map<String, String> values = new LinkedHashMap<>();
        keys(like).forEach(key -> values.put(key, preset.get(key)));
        return values;
    }

    /** The keys some preset moves off its default. */
    static Set<String> keys(Settings like) {
        Map<String, String> defaults = like.defaults().asExactText();
        Set<String> keys = new LinkedHashSet<>();
        for (String name : NAMES) {
            fileOnDefaults(name, like).asExactText().forEach((key, value) -> {
                if (!value.equals(defaults.get(key))) {
                    keys.add(key);
                }
            });
        }
        return keys;
    }

    /** The defaults with the preset's file applied. */
    private static Settings fileOnDefaults(String name, Settings like) {
        if (!NAMES.contains(name)) {
            throw new UserError("unknown preset '" + name + "': expected one of " + String.join(", ", NAMES));
        }
        Settings settings = like.defaults();
        if (!SettingsFile.readResource(resource(name), settings)) {
            throw new IllegalStateException(resource(name) + " is missing from the build");
        }
        return settings;
    }
}

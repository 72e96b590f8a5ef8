package org.openworld.engine.settings;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Each setting is described in two places that must say the same: its {@code @Setting(doc = ...)}, the short label
 * that {@code openworld settings}, the panel and the docs tables show, and the {@code @param} of its record's
 * Javadoc, the fuller text for the reader of the source (what it does and why). The test holds them to one meaning
 * without asking for one wording: every component has a {@code @param}, at least half of its label's words appear in
 * it (a label shortens its {@code @param}: "fly speed factor while Shift is held" against "factor on the fly speed
 * while Shift is held"), and of all the labels of the record its own shares the most words with it, so a
 * {@code @param} that drifted to describe another setting, or nothing that its label says, fails.
 */
class SettingDocsTest {

    private static final Path SOURCES = Path.of("src/main/java/org/openworld/engine");
    /** The record's header: its components, up to the body's brace. */
    private static final Pattern HEADER = Pattern.compile("public record \\w+\\((.*?)\\)\\s*(?:implements [\\w, ]+)?\\{",
            Pattern.DOTALL);
    /** One component: its {@code @Setting}'s doc (string literals, concatenated) and its name. */
    private static final Pattern COMPONENT = Pattern.compile(
            "@Setting\\((?:[^\"]*?)doc\\s*=\\s*((?:\"[^\"]*\"\\s*\\+?\\s*)+)[^)]*\\)\\s*[\\w.<>]+\\s+(\\w+)");
    private static final Pattern PARAM = Pattern.compile("@param\\s+(\\w+)\\s+(.*?)(?=\\n\\s*\\*\\s*@|\\n\\s*\\*/)",
            Pattern.DOTALL);
    /** The words that carry meaning: four letters or more, a plural's s dropped ("cascades" is "cascade"). */
    private static final Pattern WORD = Pattern.compile("[a-z]{4,}");

    @Test
    void everySettingsParamSaysWhatItsLabelSays() throws IOException {
        List<String> failures = new ArrayList<>();
        int checked = 0;
        try (Stream<Path> files = Files.walk(SOURCES)) {
            for (Path file : files.filter(f -> f.toString().endsWith(".java")).toList()) {
                String text = Files.readString(file);
                Matcher header = HEADER.matcher(text);
                // Setting.java itself only shows one in its Javadoc
                if (!text.contains("@Setting(") || file.endsWith("Setting.java") || !header.find()) {
                    continue;
                }
                Map<String, String> labels = new LinkedHashMap<>();
                Matcher c = COMPONENT.matcher(header.group(1));
                while (c.find()) {
                    labels.put(c.group(2), String.join("", literals(c.group(1))));
                }
                Map<String, String> params = params(text.substring(0, header.start()));
                for (Map.Entry<String, String> label : labels.entrySet()) {
                    checked++;
                    String where = file.getFileName() + " " + label.getKey();
                    String param = params.get(label.getKey());
                    if (param == null) {
                        failures.add(where + ": no @param");
                        continue;
                    }
                    double own = shared(label.getValue(), param);
                    String closest = labels.keySet().stream()
                            .max((x, y) -> Double.compare(shared(labels.get(x), param), shared(labels.get(y), param)))
                            .orElseThrow();
                    if (own < 0.5 || shared(labels.get(closest), param) > own) {
                        failures.add(String.format(Locale.ROOT, "%s: @Setting doc \"%s\" and @param \"%s\" share %.0f %% "
                                + "of the doc's words%s", where, label.getValue(), param, 100 * own,
                                closest.equals(label.getKey()) ? "" : "; the @param is nearer " + closest + "'s doc"));
                    }
                }
            }
        }
        assertTrue(checked > 100, "checked only " + checked + " settings: are the sources at " + SOURCES + "?");
        assertEquals(List.of(), failures, "settings whose two descriptions disagree");
    }

    @Test
    void theMeasureTellsAShortenedLabelFromAnotherSetting() {
        assertEquals(1.0, shared("fly speed factor while Shift is held", "factor on the fly speed while Shift is held"));
        // under half the words shared: two different settings, where a shortened label shares all of them (1.0)
        assertTrue(shared("walking speed", "eye above the ground in walk mode") < 0.5);
    }

    /** The share of {@code label}'s words that {@code param} has too. */
    static double shared(String label, String param) {
        Set<String> in = words(label);
        Set<String> both = new HashSet<>(in);
        both.retainAll(words(param));
        return in.isEmpty() ? 1 : (double) both.size() / in.size();
    }

    private static Set<String> words(String text) {
        Set<String> words = new HashSet<>();
        Matcher m = WORD.matcher(text.toLowerCase(Locale.ROOT));
        while (m.find()) {
            String w = m.group();
            words.add(w.endsWith("s") ? w.substring(0, w.length() - 1) : w);
        }
        return words;
    }

    private static List<String> literals(String concatenation) {
        List<String> parts = new ArrayList<>();
        Matcher m = Pattern.compile("\"([^\"]*)\"").matcher(concatenation);
        while (m.find()) {
            parts.add(m.group(1));
        }
        return parts;
    }

    /** The record Javadoc's {@code @param}s, each joined onto one line. */
    private static Map<String, String> params(String javadoc) {
        Map<String, String> params = new LinkedHashMap<>();
        Matcher m = PARAM.matcher(javadoc);
        while (m.find()) {
            params.put(m.group(1), m.group(2).replaceAll("\\s*\\n\\s*\\*\\s*", " ").strip());
        }
        return params;
    }
}

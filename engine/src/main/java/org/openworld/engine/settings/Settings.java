package org.openworld.engine.settings;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Collectors;

/**
 * The current value of every setting, as a world resource: one immutable record per group, replaced whole when a
 * key changes, and one on/off switch per system ({@code system.terrain}, ...), which the engine reads every frame.
 * The command line's {@code --set key=value}, {@code openworld settings}, settings files and the settings panel all
 * work through this one class, so a key cannot exist in one place and not the others.
 */
public final class Settings {

    /** What {@link #describe()} adds to the meaning of a key read only when the world is built. */
    public static final String AT_START_NOTE = " (read when the world is built)";

    /** Prefix of the systems' on/off switches: {@code system.water=off}. */
    public static final String SYSTEM_PREFIX = "system.";

    private final Map<Class<?>, SettingsGroup<?>> groups = new LinkedHashMap<>();
    private final Map<Class<?>, Record> current = new LinkedHashMap<>();
    /** Switch key → on; in the order the systems were given. */
    private final Map<String, Boolean> switches = new LinkedHashMap<>();
    private final Map<String, Boolean> switchDefaults = new LinkedHashMap<>();
    /** Values set since these settings were made, counting a value set to what it was. */
    private long changes;

    /** Groups of settings without system switches (tests of one group). */
    public Settings(List<SettingsGroup<?>> groups) {
        this(groups, Map.of());
    }

    /**
     * @param groups  every settings group
     * @param systems each system's name with whether it runs by default, in order
     */
    public Settings(List<SettingsGroup<?>> groups, Map<String, Boolean> systems) {
        for (SettingsGroup<?> group : groups) {
            if (this.groups.put(group.type(), group) != null) {
                throw new IllegalArgumentException("settings group " + group.prefix() + " registered twice");
            }
            current.put(group.type(), group.defaults());
        }
        systems.forEach((name, on) -> switchDefaults.put(SYSTEM_PREFIX + name, on));
        switches.putAll(switchDefaults);
    }

    /** New settings with the same groups and system switches, every value at its default. */
    public Settings defaults() {
        return new Settings(groups(), switchDefaults.entrySet().stream().collect(Collectors.toMap(
                e -> e.getKey().substring(SYSTEM_PREFIX.length()), Map.Entry::getValue, (a, b) -> a,
                LinkedHashMap::new)));
    }

    /**
     * Takes over every value of {@code other} at once (a settings file read into {@link #defaults()}), so no record
     * is ever checked half-changed.
     *
     * @throws IllegalArgumentException if the two do not have the same keys
     */
    public void takeOver(Settings other) {
        if (!other.keys().equals(keys())) {
            throw new IllegalArgumentException("settings with other keys cannot be taken over");
        }
        current.putAll(other.current);
        switches.putAll(other.switches);
        changes++;
    }

    /**
     * A count that grows whenever a value is set ({@link #set}, {@link #takeOver}): a system that keeps something
     * made under the settings (a shadow map) compares it with the count it was made at, instead of every value.
     */
    public long changes() {
        return changes;
    }

    /** Whether the system of this name runs; true for a system without a switch. */
    public boolean systemEnabled(String system) {
        return switches.getOrDefault(SYSTEM_PREFIX + system, true);
    }

    /** Whether these settings have an on/off switch for the system of this name. */
    public boolean hasSystem(String system) {
        return switches.containsKey(SYSTEM_PREFIX + system);
    }

    /** The system switch keys, {@code system.name}, in order. */
    public List<String> systemKeys() {
        return List.copyOf(switches.keySet());
    }

    /** The current record of a group. */
    public <R extends Record> R get(Class<R> type) {
        Record r = current.get(type);
        if (r == null) {
            throw new IllegalArgumentException("no settings group " + type.getSimpleName());
        }
        return type.cast(r);
    }

    public List<SettingsGroup<?>> groups() {
        return List.copyOf(groups.values());
    }

    /** Every key: the system switches, then group order then component order. */
    public List<String> keys() {
        List<String> keys = new ArrayList<>(switches.keySet());
        groups.values().forEach(g -> g.keys().forEach(k -> keys.add(k.key())));
        return keys;
    }

    /** Applies {@code key=value}; the error names the key and what is valid. */
    public void apply(String assignment) {
        int eq = assignment.indexOf('=');
        if (eq <= 0) {
            throw new SettingsException("'" + assignment + "': expected key=value, e.g. camera.fov=70");
        }
        set(assignment.substring(0, eq).trim(), assignment.substring(eq + 1).trim());
    }

    /** Whether a key names a file ({@link Setting#file}). */
    public boolean isFile(String key) {
        return groups.values().stream().flatMap(g -> g.keys().stream())
                .anyMatch(k -> k.key().equals(key) && k.doc().file());
    }

    /** Sets one key from text. */
    public void set(String key, String text) {
        if (switches.containsKey(key)) {
            switches.put(key, parseSwitch(key, text));
            changes++;
            return;
        }
        for (SettingsGroup<?> group : groups.values()) {
            for (SettingsGroup.Key k : group.keys()) {
                if (k.key().equals(key)) {
                    setIn(group, k, parse(k, text));
                    changes++;
                    return;
                }
            }
        }
        throw new SettingsException("unknown setting '" + key + "'" + suggestion(key)
                + "; 'openworld settings' lists every key");
    }

    private <R extends Record> void setIn(SettingsGroup<R> group, SettingsGroup.Key key, Object value) {
        current.put(group.type(), group.with(group.type().cast(current.get(group.type())), key, value));
    }

    /** The current value of a key as text, as {@code --set} would take it; numbers to six significant digits. */
    public String text(String key) {
        return format(value(key), false);
    }

    private Object value(String key) {
        if (switches.containsKey(key)) {
            return switches.get(key);
        }
        for (SettingsGroup<?> group : groups.values()) {
            for (SettingsGroup.Key k : group.keys()) {
                if (k.key().equals(key)) {
                    return valueOf(group, k);
                }
            }
        }
        throw new SettingsException("unknown setting '" + key + "'");
    }

    /** Every key with its current value as text, numbers to six significant digits (for people to read). */
    public Map<String, String> asText() {
        Map<String, String> all = new LinkedHashMap<>();
        keys().forEach(k -> all.put(k, text(k)));
        return all;
    }

    /** Every key with its current value as text that parses back to exactly that value (for settings files). */
    public Map<String, String> asExactText() {
        Map<String, String> all = new LinkedHashMap<>();
        keys().forEach(k -> all.put(k, format(value(k), true)));
        return all;
    }

    private <R extends Record> Object valueOf(SettingsGroup<R> group, SettingsGroup.Key key) {
        return group.value(group.type().cast(current.get(group.type())), key);
    }

    /**
     * A table of every key under a header: default, unit, valid values and meaning (for {@code openworld settings}).
     * Each column is as wide as its longest entry, so a long default or list of values does not push the row's
     * later columns out of line.
     */
    public String describe() {
        List<String[]> rows = new ArrayList<>();
        rows.add(new String[] {"KEY", "DEFAULT", "UNIT", "VALID", "MEANING"});
        switchDefaults.forEach((key, on) -> rows.add(new String[] {key, format(on), "", "on|off",
                "run the " + key.substring(SYSTEM_PREFIX.length()) + " system (its updates and drawing)"}));
        for (SettingsGroup<?> group : groups.values()) {
            for (SettingsGroup.Key k : group.keys()) {
                Object def = defaultOf(group, k);
                rows.add(new String[] {k.key(), def instanceof String text && text.isEmpty() ? "(none)" : format(def),
                        k.doc().unit(), validValues(k), k.doc().doc() + (k.doc().atStart() ? AT_START_NOTE : "")});
            }
        }
        int[] widths = new int[rows.get(0).length - 1];
        for (String[] row : rows) {
            for (int c = 0; c < widths.length; c++) {
                widths[c] = Math.max(widths[c], row[c].length());
            }
        }
        StringBuilder s = new StringBuilder();
        for (String[] row : rows) {
            for (int c = 0; c < widths.length; c++) {
                s.append(row[c]).append(" ".repeat(widths[c] - row[c].length() + 1));
            }
            s.append(row[widths.length]).append('\n');
        }
        return s.toString();
    }

    private static <R extends Record> Object defaultOf(SettingsGroup<R> group, SettingsGroup.Key key) {
        return group.value(group.defaults(), key);
    }

    /** The valid values of a key in words, e.g. {@code 20 .. 120} or {@code on|off}. */
    public static String validValues(SettingsGroup.Key key) {
        Class<?> t = key.type();
        if (t == boolean.class) {
            return "on|off";
        }
        if (t.isEnum()) {
            return java.util.Arrays.stream(t.getEnumConstants()).map(e -> enumText((Enum<?>) e))
                    .collect(Collectors.joining("|"));
        }
        if (t == String.class) {
            return "text";
        }
        double min = key.doc().min();
        double max = key.doc().max();
        String lo = Double.isInfinite(min) ? "" : format(t == int.class ? (Object) (int) min : min);
        String hi = Double.isInfinite(max) ? "" : format(t == int.class ? (Object) (int) max : max);
        return lo.isEmpty() && hi.isEmpty() ? "any " + t.getSimpleName() : lo + " .. " + hi;
    }

    private static Object parse(SettingsGroup.Key key, String text) {
        Class<?> t = key.type();
        String valid = validValues(key);
        try {
            if (t == String.class) {
                if (text.indexOf('\n') >= 0 || text.indexOf('\r') >= 0) {
                    // A settings file holds one key=value a line: a line break could not be saved and read back.
                    throw new SettingsException(key.key() + " is not valid: expected one line of text, found a line"
                            + " break");
                }
                return text;
            }
            if (t == boolean.class) {
                Boolean on = onOff(text);
                if (on == null) {
                    throw new NumberFormatException();
                }
                return on;
            }
            if (t.isEnum()) {
                for (Object e : t.getEnumConstants()) {
                    if (enumText((Enum<?>) e).equals(text.toLowerCase(Locale.ROOT))) {
                        return e;
                    }
                }
                throw new NumberFormatException();
            }
            double v;
            Object value;
            if (t == int.class) {
                int i = Integer.parseInt(text);
                v = i;
                value = i;
            } else if (t == double.class || t == float.class) {
                v = Double.parseDouble(text);
                if (!Double.isFinite(v)) {
                    throw new NumberFormatException();
                }
                value = t == float.class ? (Object) (float) v : (Object) v;
            } else {
                throw new IllegalStateException("settings of type " + t + " are not supported");
            }
            if (v < key.doc().min() || v > key.doc().max()) {
                throw new SettingsException(key.key() + "=" + text + " is out of range: valid is " + valid
                        + (key.doc().unit().isEmpty() ? "" : " " + key.doc().unit()));
            }
            return value;
        } catch (NumberFormatException e) {
            throw new SettingsException(key.key() + "=" + text + " is not valid: expected "
                    + (t.isEnum() || t == boolean.class ? "one of " : (t == int.class ? "an integer in " : "a number in ")) + valid);
        }
    }

    private static boolean parseSwitch(String key, String text) {
        Boolean on = onOff(text);
        if (on == null) {
            throw new SettingsException(key + "=" + text + " is not valid: expected one of on|off");
        }
        return on;
    }

    /** on/off, true/false, yes/no, 1/0 (any case); null for anything else. */
    private static Boolean onOff(String text) {
        return switch (text.toLowerCase(Locale.ROOT)) {
            case "on", "true", "yes", "1" -> true;
            case "off", "false", "no", "0" -> false;
            default -> null;
        };
    }

    private static String enumText(Enum<?> e) {
        return e.name().toLowerCase(Locale.ROOT).replace('_', '-');
    }

    private static String format(Object value) {
        return format(value, false);
    }

    /**
     * A value as {@code --set} takes it. Numbers have no exponent; {@code exact} gives the fewest digits that parse
     * back to the same double or float (0.016666666666666666), else six significant digits (0.0166667).
     */
    private static String format(Object value, boolean exact) {
        if (value instanceof Boolean b) {
            return b ? "on" : "off";
        }
        if (value instanceof Enum<?> e) {
            return enumText(e);
        }
        if (value instanceof String text) {
            return text;
        }
        if (exact && (value instanceof Double || value instanceof Float)) {
            return new java.math.BigDecimal(value.toString()).stripTrailingZeros().toPlainString();
        }
        if (value instanceof Double || value instanceof Float) {
            return new java.math.BigDecimal(((Number) value).doubleValue())
                    .round(new java.math.MathContext(6)).stripTrailingZeros().toPlainString();
        }
        return String.valueOf(value);
    }

    private String suggestion(String key) {
        return keys().stream().filter(k -> k.endsWith("." + key) || k.startsWith(key))
                .findFirst().map(k -> " (did you mean '" + k + "'?)").orElse("");
    }
}

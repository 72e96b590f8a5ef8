package org.openworld.demo;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsGroup;

/**
 * One row of the settings panel: a key of {@link Settings} and the widget that edits it. The panel's rows are made
 * from the settings themselves ({@link #all(Settings)}), the same source as {@code --set} and
 * {@code openworld settings}, so a new setting appears in the panel without a line of UI code.
 *
 * @param key     the setting's key, e.g. {@code shadow.kernel}
 * @param group   what the panel files it under: the key's prefix, e.g. {@code shadow}
 * @param label   the row's label: the key without its prefix
 * @param widget  how it is edited
 * @param choices the values a {@link Widget#CHOICE} offers, as {@code --set} takes them
 * @param min     smallest value of a slider
 * @param max     largest value of a slider
 * @param unit    the unit, shown after the value
 * @param doc     the setting's meaning, the row's tooltip
 * @param atStart whether it is read only when the world is built (the panel offers a rebuild)
 */
record PanelEntry(String key, String group, String label, Widget widget, List<String> choices, double min,
                  double max, String unit, String doc, boolean atStart) {

    /** How a row edits its value. */
    enum Widget {
        /** on/off: a checkbox. */
        CHECKBOX,
        /** one of a few names: a drop-down. */
        CHOICE,
        /** an integer in a range of at most {@link #SLIDER_INT_SPAN} values: a slider. */
        INT_SLIDER,
        /** a number in a range no wider than {@link #LOG_RATIO}: a linear slider. */
        SLIDER,
        /** a positive number over a range wider than {@link #LOG_RATIO}: a logarithmic slider. */
        LOG_SLIDER,
        /** an integer over a range too wide to drag through, or text: a field to type into. */
        FIELD
    }

    /** Ranges whose max/min is at least this are dragged on a logarithmic scale (B from 1 m to 100 km). */
    static final double LOG_RATIO = 100;
    /** Integer ranges wider than this are typed, not dragged (a seed, a flake count). */
    static final double SLIDER_INT_SPAN = 100_000;

    /** Every key of the settings, in their order, as panel rows. */
    static List<PanelEntry> all(Settings settings) {
        List<PanelEntry> entries = new ArrayList<>();
        for (String key : settings.systemKeys()) {
            String system = key.substring(Settings.SYSTEM_PREFIX.length());
            entries.add(new PanelEntry(key, "system", system, Widget.CHECKBOX, List.of(), 0, 1, "",
                    "run the " + system + " system", false));
        }
        for (SettingsGroup<?> group : settings.groups()) {
            for (SettingsGroup.Key k : group.keys()) {
                entries.add(of(group.prefix(), k));
            }
        }
        return entries;
    }

    private static PanelEntry of(String prefix, SettingsGroup.Key k) {
        Class<?> type = k.type();
        double min = k.doc().min();
        double max = k.doc().max();
        List<String> choices = List.of();
        Widget widget;
        if (type == boolean.class) {
            widget = Widget.CHECKBOX;
        } else if (type.isEnum()) {
            widget = Widget.CHOICE;
            choices = Arrays.stream(Settings.validValues(k).split("\\|")).toList();
        } else if (type == String.class || Double.isInfinite(min) || Double.isInfinite(max)) {
            widget = Widget.FIELD;
        } else if (type == int.class) {
            widget = max - min <= SLIDER_INT_SPAN ? Widget.INT_SLIDER : Widget.FIELD;
        } else {
            widget = min > 0 && max / min >= LOG_RATIO ? Widget.LOG_SLIDER : Widget.SLIDER;
        }
        return new PanelEntry(k.key(), prefix, k.key().substring(prefix.length() + 1), widget, choices, min, max,
                k.doc().unit(), k.doc().doc(), k.doc().atStart());
    }

    /**
     * The text {@code --set} takes for a slider's value: an integer slider's as an integer, else the float the slider
     * holds, in as few digits as name it exactly and without an exponent.
     */
    String text(float value) {
        if (widget == Widget.INT_SLIDER) {
            return Integer.toString(Math.round(value));
        }
        return new BigDecimal(Float.toString(value)).stripTrailingZeros().toPlainString();
    }
}

package org.openworld.engine.core;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Numbers a system wants to report per frame, e.g. {@code terrain.visible} patches. A world resource, cleared by the
 * engine at the start of every frame; {@code bench} writes each counter as a column of {@code frames.csv}.
 */
public final class Counters {

    private final Map<String, Double> values = new LinkedHashMap<>();

    public void put(String name, double value) {
        values.put(name, value);
    }

    /** Adds to a counter, e.g. patches drawn in each pass. */
    public void add(String name, double value) {
        values.merge(name, value, Double::sum);
    }

    public Map<String, Double> snapshot() {
        return new LinkedHashMap<>(values);
    }

    /** Called by the engine at the start of each frame. */
    public void clear() {
        values.clear();
    }
}

package org.openworld.engine.core;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Numbers a system wants to report per frame, e.g. {@code terrain.main.patches}, keyed by {@link Counter}. A world
 * resource, cleared by the engine at the start of every frame; {@code bench} writes each counter as a column of
 * {@code frames.csv}.
 */
public final class Counters {

    private final Map<Counter, Double> values = new LinkedHashMap<>();

    public void put(Counter counter, double value) {
        values.put(counter, value);
    }

    /** Adds to a counter, e.g. patches drawn in each pass. */
    public void add(Counter counter, double value) {
        values.merge(counter, value, Double::sum);
    }

    /** This frame's value of {@code counter}, or null when it was not counted. */
    public Double get(Counter counter) {
        return values.get(counter);
    }

    /** The counters by {@link Counter#name}, in the order they were first counted this frame. */
    public Map<String, Double> snapshot() {
        Map<String, Double> named = new LinkedHashMap<>();
        values.forEach((counter, value) -> named.put(counter.name(), value));
        return named;
    }

    /** Called by the engine at the start of each frame. */
    public void clear() {
        values.clear();
    }
}

package org.openworld.engine.core;

/**
 * The key of a number a system reports per frame ({@link Counters}): the system, the pass when it is counted per
 * pass, and the measure. Systems keep their counters as constants ({@code Counter.of("trees", "drawn")}) and key a
 * pass's count with {@link #in}, so no name is assembled from strings where it is counted.
 *
 * @param system  the reporting system's name, as in its {@link SystemSpec}
 * @param pass    the pass counted in, or null for a count of the whole frame
 * @param measure what is counted, lower case with '-' ({@code select-ms})
 */
public record Counter(String system, Pass pass, String measure) {

    public Counter {
        for (String part : new String[] {system, measure}) {
            if (part == null || !part.matches("[a-z][a-z0-9-]*")) {
                throw new IllegalArgumentException("counter part '" + part + "': use lower case letters, digits and '-'");
            }
        }
    }

    /** A count of the whole frame. */
    public static Counter of(String system, String measure) {
        return new Counter(system, null, measure);
    }

    /** The same measure counted in {@code counted}. */
    public Counter in(Pass counted) {
        return new Counter(system, counted, measure);
    }

    /**
     * The name the frame records and {@code bench}'s {@code frames.csv} column carry: {@code system.measure}, or
     * {@code system.pass.measure} ({@code terrain.main.patches}).
     */
    public String name() {
        return system + (pass == null ? "" : "." + pass.label()) + "." + measure;
    }
}

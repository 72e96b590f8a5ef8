package org.openworld.engine.terrain.heights;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * Wall time of each stage of making the terrain data ({@code synthesis} or {@code import}, {@code pyramid},
 * {@code snow map}), in the order they ran, for the {@code heightmap} command and the terrain system to report. The
 * engine prints nothing itself: a caller who wants progress lines passes a listener.
 */
public final class StageTimes {

    /** One finished stage and its wall time, milliseconds. */
    public record Stage(String name, double ms) {
    }

    private final List<Stage> stages = new ArrayList<>();
    private final Consumer<Stage> listener;

    /** Records silently. */
    public StageTimes() {
        this(stage -> { });
    }

    /** Records, and tells {@code listener} about each stage as it finishes. */
    public StageTimes(Consumer<Stage> listener) {
        this.listener = listener;
    }

    /** Runs one stage, records its wall time and returns its result. */
    public <T> T time(String name, Supplier<T> work) {
        long start = System.nanoTime();
        T result = work.get();
        Stage stage = new Stage(name, (System.nanoTime() - start) / 1e6);
        stages.add(stage);
        listener.accept(stage);
        return result;
    }

    /** The stages in the order they ran. */
    public List<Stage> stages() {
        return List.copyOf(stages);
    }

    /** Sum of the stages' times, milliseconds. */
    public double totalMs() {
        return stages.stream().mapToDouble(Stage::ms).sum();
    }
}

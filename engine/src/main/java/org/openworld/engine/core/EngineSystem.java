package org.openworld.engine.core;

import java.util.List;
import org.openworld.engine.settings.SettingsGroup;

/**
 * A system: one technique, with a small lifecycle (STYLE.md 6).
 * <ol>
 *   <li>{@link #init}: create GPU resources, spawn entities, publish resources (once, on the GL thread);</li>
 *   <li>{@link #update}: advance by one fixed simulation step;</li>
 *   <li>{@link #render}: draw in one pass, for each pass declared in {@link #spec()};</li>
 *   <li>{@link #close}: free what {@code init} made outside {@link EngineContext#own} (a worker thread, native
 *       memory), on the GL thread; also called after an {@code init} that failed half-way, so it must skip what was
 *       never made. What was handed to {@code context.own} the engine closes afterwards, newest first: most
 *       systems write no {@code close} at all.</li>
 * </ol>
 * Switching a system off ({@code Engine.setEnabled}) skips its update and render; it never reallocates.
 */
public interface EngineSystem extends AutoCloseable {

    /** Name, reads, writes, order constraints and passes; read once when the engine starts. */
    SystemSpec spec();

    /** The settings groups this system reads; their keys appear in {@code --set} and {@code openworld settings}. */
    default List<SettingsGroup<?>> settings() {
        return List.of();
    }

    default void init(EngineContext context) {
    }

    /**
     * @param world the shared world
     * @param step  the fixed simulation step, seconds
     */
    default void update(World world, double step) {
    }

    default void render(Pass pass, RenderContext context) {
    }

    @Override
    default void close() {
    }
}

package org.openworld.engine.core;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.openworld.engine.settings.SettingsGroup;

/**
 * A system: one technique, with a small lifecycle (CONTRIBUTING.md, "Lifecycle").
 * <ol>
 *   <li>{@link #init}: create GPU resources, spawn entities, publish resources (once, on the GL thread);</li>
 *   <li>{@link #update}: advance by one fixed simulation step;</li>
 *   <li>{@link #beginPass}: set up GL state that holds for a whole pass, before anyone draws in it;</li>
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

    /**
     * Numbers this system's Java and its shaders share (the sky's table sizes), each passed to every program as
     * {@code #define NAME value}: written once, in Java, where a shader would otherwise repeat them. Read once, when
     * the engine starts, before any program is compiled.
     */
    default Map<String, Number> shaderConstants() {
        return Map.of();
    }

    /** Every system's {@link #shaderConstants}, for the engine's shader library. */
    static Map<String, Number> shaderConstants(List<? extends EngineSystem> systems) {
        Map<String, Number> all = new LinkedHashMap<>();
        systems.forEach(system -> all.putAll(system.shaderConstants()));
        return all;
    }

    default void init(EngineContext context) {
    }

    /**
     * @param world the shared world
     * @param step  the fixed simulation step, seconds
     */
    default void update(World world, double step) {
    }

    /**
     * Called at the start of each pass this system works in (draws in or prepares), once per view of the pass: after
     * the engine has bound the pass's target and cleared it (OVERLAY, drawn over the picture, is not cleared), before
     * any system's {@link #render} in it, and only while this system is switched on. It is for GL state that the
     * systems drawing <em>before</em> this one must already obey: the water's stencil method has every fragment drawn
     * in MAIN mark the stencil, so it sets that rule here, and no other system need know of it; and it scissors the
     * reflection pass to the water's part of the screen. Each pass starts without a scissor, its target cleared
     * whole.
     *
     * <p>Every working system's hook runs, in frame order, before the first one draws; so set only state that this
     * system's technique owns and that the others' drawing does not change. The engine puts back a neutral state
     * after the frame. Most systems need nothing here.
     */
    default void beginPass(Pass pass, RenderContext context) {
    }

    default void render(Pass pass, RenderContext context) {
    }

    @Override
    default void close() {
    }
}

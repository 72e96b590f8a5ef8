package org.openworld.engine.core;

import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.ShaderLibrary;
import org.openworld.engine.settings.Settings;

/**
 * What a system gets in {@link EngineSystem#init}: the GL context to create objects with (they count against it),
 * the world, the shader library and the settings.
 *
 * @param gl       the context; every GL object is created with it
 * @param world    the shared world
 * @param shaders  builds shader programs from {@code shaders/} and reloads them in dev mode
 * @param settings the settings resource (also in the world)
 * @param owned    what this system has made: the engine closes it, newest first, after the system's own
 *                 {@code close()}
 */
public record EngineContext(GlContext gl, World world, ShaderLibrary shaders, Settings settings, Owned owned) {

    /**
     * Hands {@code thing} to the engine to close when the system is closed (after the system's own {@code close()},
     * newest first, going on past a failing close), and returns it: {@code program = context.own(shaders.build(..))}.
     */
    public <T extends AutoCloseable> T own(T thing) {
        return owned.own(thing);
    }
}

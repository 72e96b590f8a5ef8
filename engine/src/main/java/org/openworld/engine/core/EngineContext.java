package org.openworld.engine.core;

import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Labelled;
import org.openworld.engine.gl.ShaderLibrary;
import org.openworld.engine.settings.Settings;

/**
 * What a system gets in {@link EngineSystem#init}: the GL context to create objects with (they count against it),
 * the world, the shader library, the settings, and the owner of what it makes.
 *
 * <p>Every GL object a system makes goes to {@link #own(String, Labelled)} with its role, in the line that makes it:
 * {@code heights = context.own("heights", Texture2D.withMips(..))}. The engine closes it when the system is closed,
 * newest first, going on past a failing close, so a system needs no {@code close()} of its own; and the object is
 * labelled {@code system.role} ({@code terrain.heights}) for GPU debuggers, as the system's timer spans are named
 * {@code main.terrain}. An object re-made at run time (a target at a new size) goes through
 * {@link Owned#replace(String, AutoCloseable, Labelled) owned().replace}.
 *
 * @param gl       the context; every GL object is created with it
 * @param world    the shared world
 * @param shaders  builds shader programs from {@code shaders/} and reloads them in dev mode
 * @param settings the settings resource (also in the world)
 * @param owned    what this system has made, labelled with the system's name: the engine closes it, newest first,
 *                 after the system's own {@code close()}
 */
public record EngineContext(GlContext gl, World world, ShaderLibrary shaders, Settings settings, Owned owned) {

    /**
     * Hands the GL object {@code thing} to the engine to close when the system is closed, labels it
     * {@code system.role}, and returns it: {@code program = context.own("program", shaders.program(..))}.
     */
    public <T extends Labelled> T own(String role, T thing) {
        return owned.own(role, thing);
    }

    /**
     * Hands over something that is not itself a GL object but must be closed with the system (a worker pool); GL
     * objects go through {@link #own(String, Labelled)}, which also labels them.
     */
    public <T extends AutoCloseable> T own(T thing) {
        return owned.own(thing);
    }
}

package org.openworld.engine.gl;

/**
 * A GL object, or a group of them, that takes a debug label ({@link GlDebug#label}): what a system hands to
 * {@code EngineContext.own(role, thing)} is labelled {@code system.role}, e.g. {@code terrain.heights}, and a group
 * labels its parts below that name ({@code water.reflection.color}, {@code water.reflection.depth}).
 */
public interface Labelled extends AutoCloseable {

    /** Names this object (and its parts, as {@code name.part}) for GPU debuggers. */
    void label(String name);
}

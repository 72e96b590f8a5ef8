package org.openworld.engine.core;

import java.util.EnumSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * What a system declares about itself, from which the engine derives the frame order: the resource and component
 * classes it reads and writes, the systems it must follow, the passes it draws in and the {@link Layer} it draws in.
 *
 * <p>Types and names keep the order they are declared in (Set.of would shuffle them per run), so
 * {@code openworld info --frame} prints the same text every time.
 *
 * <p>Written as a small builder so a declaration reads like a sentence:
 * <pre>{@code
 * SystemSpec.named("camera").reads(InputState.class, HeightField.class).writes(Camera.class)
 * }</pre>
 * Reads, writes and followed systems keep the order they were declared in, so {@code openworld info} prints the same
 * text on every run.
 */
public final class SystemSpec {

    private final String name;
    private final Set<Class<?>> reads = new LinkedHashSet<>();
    private final Set<Class<?>> writes = new LinkedHashSet<>();
    private final Set<Class<?>> published = new LinkedHashSet<>();
    private final Set<String> after = new LinkedHashSet<>();
    private final Set<Pass> passes = EnumSet.noneOf(Pass.class);
    private final Set<Pass> prepared = EnumSet.noneOf(Pass.class);
    private Layer layer = Layer.OPAQUE;
    private boolean offByDefault;
    private boolean updatesOnGpu;

    private SystemSpec(String name) {
        if (!name.matches("[a-z][a-z0-9-]*")) {
            throw new IllegalArgumentException("system name '" + name + "': use lower case letters, digits and '-'");
        }
        this.name = name;
    }

    public static SystemSpec named(String name) {
        return new SystemSpec(name);
    }

    /** Resources or components this system reads; it runs after every system that writes them. */
    public SystemSpec reads(Class<?>... types) {
        reads.addAll(List.of(types));
        return this;
    }

    /** Resources or components this system writes; two writers of one type must be ordered with {@link #after}. */
    public SystemSpec writes(Class<?>... types) {
        writes.addAll(List.of(types));
        return this;
    }

    /**
     * Resources this system puts in the world when it starts and renews only when a setting changes (the water's
     * level): the world's layout rather than a frame's data. They order nothing: any system may read them at any point
     * of the frame, one running before the publisher seeing a change a step late. A type written in the frame must be
     * declared with {@link #writes} instead, which puts its readers after the writer; a published one keeps a reader
     * free to go before the publisher (the trees, opaque, before the water that draws over them).
     */
    public SystemSpec publishes(Class<?>... types) {
        published.addAll(List.of(types));
        return this;
    }

    /**
     * Systems, by name, that must run before this one (in update and in every pass). The shipped systems need none
     * (what they read and write and their layers order them all); it orders two writers of one type, which
     * {@link SystemOrder} otherwise refuses, and lets a scene's own system follow a named one.
     */
    public SystemSpec after(String... systems) {
        after.addAll(List.of(systems));
        return this;
    }

    /** Passes this system draws in. */
    public SystemSpec draws(Pass... drawn) {
        passes.addAll(Set.of(drawn));
        return this;
    }

    /**
     * Passes this system works in without drawing, before the systems that draw read its results (culling tests the
     * pass camera). Such a system never makes a pass run by itself: a pass runs when a system draws in it.
     */
    public SystemSpec prepares(Pass... passesPrepared) {
        prepared.addAll(Set.of(passesPrepared));
        return this;
    }

    /** The layer it draws in, {@link Layer#OPAQUE} unless declared (the sky, the water, the particles declare theirs). */
    public SystemSpec layer(Layer drawnIn) {
        layer = drawnIn;
        return this;
    }

    /**
     * Its update issues GPU work (the snow's transform-feedback step, the sky's panorama): the engine times each
     * update on the GPU as a span labelled {@code update.name}, beside the passes' spans.
     */
    public SystemSpec updatesOnGpu() {
        updatesOnGpu = true;
        return this;
    }

    /**
     * It does not run until switched on ({@code --set system.name=on}, or the settings panel): for what a scene has
     * ready but the default picture leaves out, such as snowfall.
     */
    public SystemSpec offByDefault() {
        offByDefault = true;
        return this;
    }

    public String name() {
        return name;
    }

    public Set<Class<?>> reads() {
        return reads;
    }

    public Set<Class<?>> writes() {
        return writes;
    }

    /** The resources this system publishes: see {@link #publishes}. */
    public Set<Class<?>> published() {
        return published;
    }

    public Set<String> after() {
        return after;
    }

    /** The passes this system draws in. */
    public Set<Pass> passes() {
        return passes;
    }

    /** The layer it draws in: see {@link Layer}. */
    public Layer layer() {
        return layer;
    }

    public boolean isOffByDefault() {
        return offByDefault;
    }

    public boolean isUpdatedOnGpu() {
        return updatesOnGpu;
    }

    /** The passes this system prepares without drawing. */
    public Set<Pass> prepared() {
        return prepared;
    }
}

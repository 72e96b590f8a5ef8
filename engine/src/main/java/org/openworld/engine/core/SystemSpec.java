package org.openworld.engine.core;

import java.util.EnumSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * What a system declares about itself, from which the engine derives the frame order: the resource and component
 * classes it reads and writes, the systems it must follow, and the passes it draws in.
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
    private boolean transparent;
    private boolean overOpaque;
    private boolean background;
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

    /** Systems, by name, that must run before this one (in update and in every pass). */
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

    /**
     * Its drawing is blended over the finished opaque picture (particles): it follows every other system that draws in
     * one of its passes, without naming them, so it stays last whichever systems a scene has.
     */
    public SystemSpec transparent() {
        transparent = true;
        return this;
    }

    /**
     * It draws over the finished opaque picture of its passes and reads it (the water copies the scene's colour and
     * depth to show what lies behind and under it): it follows every system that draws opaque in one of its passes
     * (neither {@link #transparent()} nor this; the {@link #background()} included), without naming them, so a new
     * opaque system is behind the water whatever it is called. Transparent systems still follow it.
     */
    public SystemSpec overOpaque() {
        overOpaque = true;
        return this;
    }

    /**
     * It draws the background of its passes, what lies behind every surface (the sky): in each pass it draws after
     * every opaque system of that pass (neither transparent, nor over the opaque, nor another background), without
     * naming them ({@link SystemOrder#drawOrder}), while its update keeps its place in the frame order, so an opaque
     * system may read what it writes (the sun). It draws at the far plane with the depth test on and depth writes
     * off, so the pixels an opaque surface already covers fail the depth test before they are shaded (early depth
     * rejection) and each pixel is shaded once. Systems drawn over the opaque picture, and transparent ones, still
     * follow it. Work the opaque systems need from it (tables, maps) it does before the passes, in its update.
     */
    public SystemSpec background() {
        background = true;
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

    public boolean isTransparent() {
        return transparent;
    }

    public boolean isOverOpaque() {
        return overOpaque;
    }

    public boolean isBackground() {
        return background;
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

package org.openworld.engine.core;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.openworld.engine.gl.Labelled;

/**
 * What one owner (a system, the engine) has made and must close: objects are added as they are made and closed in
 * reverse order, so a thing is closed before whatever it was made from. Closing goes on past a close that throws and
 * reports every failure at the end, the first as the exception and the others suppressed in it; an object is never
 * closed twice. An init that fails half-way therefore leaves nothing behind: what was owned so far is closed, what
 * was never made was never added.
 *
 * <p>A GL object is owned with its role, {@code own("heights", texture)}, and labelled {@code owner.role}
 * ({@code terrain.heights}) for GPU debuggers ({@link Labelled}), in the style of the owner's timer spans.
 */
public final class Owned implements AutoCloseable {

    private final String owner;
    private final List<AutoCloseable> things = new ArrayList<>();

    /** @param owner the first part of every label: a system's name, or {@code engine} */
    public Owned(String owner) {
        this.owner = owner;
    }

    /** An owner whose objects are labelled by their role alone. */
    public Owned() {
        this(null);
    }

    /**
     * Takes a GL object into ownership as {@link #own(AutoCloseable)} does, and labels it {@code owner.role}:
     * {@code heights = owned.own("heights", Texture2D.withMips(..))}.
     */
    public <T extends Labelled> T own(String role, T thing) {
        own(thing);
        thing.label(label(role));
        return thing;
    }

    /** {@link #replace(AutoCloseable, AutoCloseable)} for a GL object, labelled {@code owner.role} as it is owned. */
    public <T extends Labelled> T replace(String role, AutoCloseable old, T fresh) {
        replace(old, fresh);
        fresh.label(label(role));
        return fresh;
    }

    /** The label of the object with this role: {@code owner.role}. */
    public String label(String role) {
        return owner == null ? role : owner + "." + role;
    }

    /** Takes {@code thing} into ownership and hands it back, so a field is set in one line: {@code x = own(make())}. */
    public <T extends AutoCloseable> T own(T thing) {
        if (thing == null) {
            throw new IllegalArgumentException("cannot own null");
        }
        things.add(thing);
        return thing;
    }

    /**
     * Closes {@code old} now and owns {@code fresh} in its place (a target re-made at a new size): the old one is
     * dropped from the list, so it is not closed again at the end.
     */
    public <T extends AutoCloseable> T replace(AutoCloseable old, T fresh) {
        drop(old);
        return own(fresh);
    }

    /**
     * Closes {@code old} now, if it is owned here, and owns it no longer (a target that is not re-made); null or an
     * object owned elsewhere is left alone.
     */
    public void drop(AutoCloseable old) {
        if (old != null && things.remove(old)) {
            closeAll(List.of(old));
        }
    }

    /** How many objects are owned now. */
    public int size() {
        return things.size();
    }

    /** Closes every owned object, newest first, continuing past failures; then owns nothing. */
    @Override
    public void close() {
        List<AutoCloseable> reversed = new ArrayList<>(things);
        things.clear();
        Collections.reverse(reversed);
        closeAll(reversed);
    }

    private static void closeAll(List<AutoCloseable> list) {
        RuntimeException failure = null;
        for (AutoCloseable thing : list) {
            try {
                thing.close();
            } catch (Exception e) {
                RuntimeException wrapped = e instanceof RuntimeException r ? r
                        : new IllegalStateException("closing " + thing + " failed: " + e.getMessage(), e);
                if (failure == null) {
                    failure = wrapped;
                } else {
                    failure.addSuppressed(wrapped);
                }
            }
        }
        if (failure != null) {
            throw failure;
        }
    }
}

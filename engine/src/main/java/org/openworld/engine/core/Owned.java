package org.openworld.engine.core;

import java.util.ArrayList;
import java.util.List;

/**
 * What one owner (a system, the engine) has made and must close: objects are added as they are made and closed in
 * reverse order, so a thing is closed before whatever it was made from. Closing goes on past a close that throws and
 * reports every failure at the end, the first as the exception and the others suppressed in it; an object is never
 * closed twice. An init that fails half-way therefore leaves nothing behind: what was owned so far is closed, what
 * was never made was never added.
 */
public final class Owned implements AutoCloseable {

    private final List<AutoCloseable> things = new ArrayList<>();

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
        if (old != null && things.remove(old)) {
            closeAll(List.of(old));
        }
        return own(fresh);
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
        java.util.Collections.reverse(reversed);
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

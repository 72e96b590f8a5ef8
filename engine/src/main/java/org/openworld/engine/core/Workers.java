package org.openworld.engine.core;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ThreadFactory;

/**
 * The systems' background threads (the sky's tables, the forests' placement, the grass field, the terrain's blocks):
 * daemon threads, so work still under way never keeps the program from ending, each named for its owner, so a thread
 * dump or a profile says whose work it is.
 */
public final class Workers {

    private Workers() {
    }

    /** One daemon thread called {@code name} that runs the tasks one after another, in the order they came. */
    public static ExecutorService single(String name) {
        return Executors.newSingleThreadExecutor(named(name, Thread.NORM_PRIORITY));
    }

    /** Makes daemon threads called {@code name} at {@code priority} ({@link Thread#MIN_PRIORITY} for work that may wait). */
    public static ThreadFactory named(String name, int priority) {
        return r -> {
            Thread t = new Thread(r, name);
            t.setDaemon(true);
            t.setPriority(priority);
            return t;
        };
    }
}

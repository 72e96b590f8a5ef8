package org.openworld.demo;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * Turns SIGINT (Ctrl+C) and SIGTERM into a polite request to stop, so that a long run can write what it has before
 * the JVM ends. The JVM answers both signals by running its shutdown hooks and then exiting with 128 + the signal's
 * number: 130 for SIGINT, 143 for SIGTERM, as a shell reports a process a signal ended. This class's hook only sets
 * a flag that the main thread reads between frames ({@link #requested()}) and waits, at most {@link #WAIT_MS}, for
 * the main thread to say it is done ({@link #close()}). The hook never touches OpenGL: the context belongs to the
 * main thread, and the main thread keeps running while the hooks do.
 *
 * <p>Limits: SIGKILL (and a crash of the JVM) runs no hook; a signal before {@link #install()} ends the JVM at
 * once; a main thread that takes longer than {@link #WAIT_MS} to finish is cut off where it is.
 */
final class StopSignal implements AutoCloseable {

    /**
     * How long the hook waits for the main thread: the frame in flight, then the write. Writing a stopped bench run
     * of a few thousand frames takes about 1 s on the project's 2-core machine, 3 s at a load average of 15 (the
     * chart's cost is bounded by its width, and Java2D is warmed up before the frames); a minute leaves room for a
     * slow frame and a run of several hundred thousand frames, whose frames.csv is the longest part.
     */
    static final long WAIT_MS = 60_000;

    private final CountDownLatch done = new CountDownLatch(1);
    private final Thread hook = new Thread(this::stopAndWait, "openworld-stop-signal");
    private volatile boolean requested;

    private StopSignal() {
    }

    /** Starts listening for SIGINT and SIGTERM until {@link #close()}. */
    static StopSignal install() {
        StopSignal signal = new StopSignal();
        Runtime.getRuntime().addShutdownHook(signal.hook);
        return signal;
    }

    /** Whether a signal asked the run to stop. */
    boolean requested() {
        return requested;
    }

    /** The main thread is done: lets a waiting hook return (the JVM then exits) or stops listening. */
    @Override
    public void close() {
        done.countDown();
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException shuttingDown) {
            // the hook is running: it returns now that the latch is open
        }
    }

    private void stopAndWait() {
        requested = true;
        try {
            done.await(WAIT_MS, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}

package org.openworld.engine.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.ExecutorService;
import org.junit.jupiter.api.Test;

class WorkersTest {

    @Test
    void aWorkerIsANamedDaemonThatNeverHoldsTheProgramOpen() throws Exception {
        ExecutorService worker = Workers.single("test-worker");
        try {
            Thread t = worker.submit(Thread::currentThread).get();
            assertEquals("test-worker", t.getName());
            assertTrue(t.isDaemon(), "a busy worker must not keep the JVM from exiting");
            assertEquals(Thread.NORM_PRIORITY, t.getPriority());
        } finally {
            worker.shutdownNow();
        }
    }

    @Test
    void aLowPriorityFactoryMakesLowPriorityDaemons() {
        Thread t = Workers.named("blocks", Thread.MIN_PRIORITY).newThread(() -> { });
        assertEquals("blocks", t.getName());
        assertTrue(t.isDaemon());
        assertEquals(Thread.MIN_PRIORITY, t.getPriority());
    }
}

package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL11C.glFlush;
import static org.lwjgl.opengl.GL32C.*;

import java.util.ArrayDeque;
import java.util.Deque;

/**
 * Keeps the CPU at most {@link #MAX_FRAMES_IN_FLIGHT} frames ahead of the GPU, as a window's swap chain does. A
 * headless run has no swap to wait on, so without this the CPU would queue frame after frame and the timings would
 * measure the queue rather than the frame. One fence per frame; waiting on the oldest when too many are pending.
 */
public final class FrameThrottle implements AutoCloseable {

    /** Frames the CPU may run ahead of the GPU: two, like double buffering with a queued frame. */
    public static final int MAX_FRAMES_IN_FLIGHT = 2;
    /** Longest wait for one frame before giving up on the fence, nanoseconds (10 s). */
    private static final long TIMEOUT_NS = 10_000_000_000L;

    private final GlContext gl;
    private final Deque<Long> fences = new ArrayDeque<>();

    public FrameThrottle(GlContext gl) {
        this.gl = gl;
    }

    /** Marks the end of a frame's commands and waits while too many frames are in flight. */
    public void endFrame() {
        fences.add(glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0));
        gl.objects().created(GlObjects.Kind.SYNC);
        glFlush();
        while (fences.size() > MAX_FRAMES_IN_FLIGHT) {
            long oldest = fences.pop();
            glClientWaitSync(oldest, GL_SYNC_FLUSH_COMMANDS_BIT, TIMEOUT_NS);
            delete(oldest);
        }
    }

    private void delete(long fence) {
        glDeleteSync(fence);
        gl.objects().deleted(GlObjects.Kind.SYNC);
    }

    @Override
    public void close() {
        while (!fences.isEmpty()) {
            delete(fences.pop());
        }
    }
}

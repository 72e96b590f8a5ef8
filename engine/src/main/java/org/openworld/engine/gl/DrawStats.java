package org.openworld.engine.gl;

/** Draw calls and triangles submitted in one frame, counted by {@link Mesh} and reset by the engine each frame. */
public final class DrawStats {

    private long drawCalls;
    private long triangles;

    /** Counts draws made outside {@link Mesh}, e.g. a full-screen triangle. */
    public void add(long calls, long tris) {
        drawCalls += calls;
        triangles += tris;
    }

    public long drawCalls() {
        return drawCalls;
    }

    public long triangles() {
        return triangles;
    }

    public void reset() {
        drawCalls = 0;
        triangles = 0;
    }
}

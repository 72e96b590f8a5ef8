package org.openworld.engine.terrain.stream;

/**
 * A frame's allowance of work that may wait (the sky's passes over blocks no pass draws yet, {@link StreamedSky}):
 * each frame takes jobs, each with its cost, until the next would overspend, so a burst of arrivals is spread over
 * the frames after it instead of stalling the one it arrives in. A job dearer than the whole allowance is taken
 * alone, in a frame of its own, so every job is done at last; jobs that may not wait (what a pass is about to draw)
 * are {@linkplain #spend spent} outside the allowance's check and leave less for the rest of the frame. GL-free:
 * {@code FrameBudgetTest} checks both promises.
 */
final class FrameBudget {

    private final long perFrame;
    private long spent;

    /** An allowance of {@code perFrame} units (any unit the caller's costs share) a frame. */
    FrameBudget(long perFrame) {
        if (perFrame <= 0) {
            throw new IllegalArgumentException("a frame's budget must be positive, got " + perFrame);
        }
        this.perFrame = perFrame;
    }

    /**
     * Whether a job of this cost fits what is left of this frame's allowance, or is the frame's first; if so it is
     * spent.
     */
    boolean take(long cost) {
        if (spent > 0 && spent + cost > perFrame) {
            return false;
        }
        spent += cost;
        return true;
    }

    /** Spends this cost whatever is left: a job that may not wait. */
    void spend(long cost) {
        spent += cost;
    }

    /** What this frame has spent so far. */
    long spent() {
        return spent;
    }

    /** Ends the frame: the next one starts with the whole allowance. */
    void nextFrame() {
        spent = 0;
    }
}

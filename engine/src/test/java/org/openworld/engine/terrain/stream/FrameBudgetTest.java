package org.openworld.engine.terrain.stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * {@link FrameBudget}: a frame never spends more than its allowance on jobs that may wait (unless one job alone is
 * dearer), and every job is done at last, however bursty the arrivals.
 */
class FrameBudgetTest {

    /**
     * Bursts of jobs of random cost (the sky's passes: a level-0 block costs 23 distances, a level-7 block 9) arrive
     * every few frames, some dearer than the allowance; the frames take them in order. No frame's spending exceeds
     * the allowance except a frame that took one job alone, each frame with work waiting takes at least one, and
     * the queue is empty after the arrivals stop, within as many frames as jobs arrived.
     */
    @Test
    void aFrameNeverSpendsMoreThanItsAllowanceAndEveryJobIsDone() {
        long allowance = 23;
        FrameBudget budget = new FrameBudget(allowance);
        SplittableRandom random = new SplittableRandom(40);
        Deque<Long> queue = new ArrayDeque<>();
        int arrived = 0;
        int done = 0;
        int arrivalFrames = 500;
        int frame = 0;
        for (; frame < arrivalFrames || !queue.isEmpty(); frame++) {
            assertTrue(frame < arrivalFrames + 8 * arrivalFrames, "the queue never empties");
            if (frame < arrivalFrames && frame % 25 == 0) { // a burst: a column of blocks, a few of them too dear
                for (int i = 0; i < 16; i++) {
                    queue.add(random.nextInt(10) == 0 ? allowance + 1 + random.nextInt(20) : 9 + random.nextInt(15));
                    arrived++;
                }
            }
            int taken = 0;
            long spent = 0;
            while (!queue.isEmpty() && budget.take(queue.peek())) {
                spent += queue.poll();
                taken++;
            }
            assertEquals(spent, budget.spent(), "the budget counts what it handed out");
            assertTrue(spent <= allowance || taken == 1, "frame " + frame + " spent " + spent + " on " + taken
                    + " jobs, over its allowance of " + allowance);
            assertTrue(queue.isEmpty() || taken >= 1, "frame " + frame + " took nothing with work waiting");
            done += taken;
            budget.nextFrame();
        }
        assertEquals(arrived, done);
        // each frame with work waiting took a job, so the last one came within as many frames as jobs arrived
        assertTrue(frame <= arrived + arrivalFrames, frame + " frames for " + arrived + " jobs");
    }

    /**
     * Work that may not wait is spent whatever the allowance, and leaves that much less for the rest of the frame:
     * a frame that spent its allowance on it takes nothing more, and the next frame has the whole allowance again.
     */
    @Test
    void workThatMayNotWaitLeavesLessForTheRest() {
        FrameBudget budget = new FrameBudget(10);
        budget.spend(8);
        assertTrue(budget.take(2), "what is left pays for a job that fits it");
        assertFalse(budget.take(1), "nothing is left");
        budget.nextFrame();
        budget.spend(30);
        assertEquals(30, budget.spent(), "work that may not wait is spent beyond the allowance");
        assertFalse(budget.take(1), "an overspent frame takes nothing more");
        budget.nextFrame();
        assertTrue(budget.take(10), "the next frame has the whole allowance");
        assertFalse(budget.take(1));
        assertThrows(IllegalArgumentException.class, () -> new FrameBudget(0));
    }
}

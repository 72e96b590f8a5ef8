package org.openworld.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The fixed-step clock: whole steps only, the remainder carried, the backlog dropped at the cap. */
class FixedStepClockTest {

    @Test
    void realTimeBecomesWholeStepsAndTheRemainderWaits() {
        FixedStepClock clock = new FixedStepClock();
        assertEquals(3, clock.stepsOwed(0.03, 0.01, 10), "0.03 s is 3 steps of 0.01 s despite rounding");
        assertEquals(0, clock.stepsOwed(0.006, 0.01, 10), "0.006 s owes no step yet");
        assertEquals(1, clock.stepsOwed(0.006, 0.01, 10), "0.012 s owed by now: one step, 0.002 s left");
    }

    @Test
    void aSlowFrameRunsAtMostTheCapAndForgetsTheRest() {
        FixedStepClock clock = new FixedStepClock();
        assertEquals(4, clock.stepsOwed(1.0, 0.01, 4));
        assertEquals(0, clock.stepsOwed(0.005, 0.01, 4), "the 0.96 s not run is not owed later");
    }

    @Test
    void simulationTimeIsTheSumOfTheStepsRun() {
        FixedStepClock clock = new FixedStepClock();
        for (int i = 0; i < 100; i++) {
            clock.stepped(0.01);
        }
        // doubles: a sum of exact steps, equal to round-off
        assertEquals(1.0, clock.simTime(), 1e-12);
    }
}

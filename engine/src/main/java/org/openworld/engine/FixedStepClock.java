package org.openworld.engine;

/**
 * The simulation's clock: time advances only in whole fixed steps, so a run replays identically whatever the frame
 * rate (docs/design.md, "The frame"). The window feeds it real time and runs the steps it owes; a benchmark runs one
 * step per frame.
 *
 * <p>The time owed is {@code unsimulated += realSeconds}; while at least one step is owed and fewer than
 * {@code maxSteps} have run this frame, one more step runs and {@code unsimulated −= step}. A frame that would owe
 * more than {@code maxSteps} drops the rest: the simulation slows down instead of spiralling (each step making the
 * next frame slower still).
 */
final class FixedStepClock {

    /**
     * Slack when comparing the time not yet simulated with the step, seconds: far below any step, far above the
     * rounding error of the sums, so 0.03 s at a 0.01 s step runs 3 steps, not 2 (0.03 − 0.01 − 0.01 &lt; 0.01 in
     * doubles).
     */
    private static final double STEP_SLACK = 1e-9;

    private double simTime;
    private double unsimulated;

    /** Simulation time, seconds: the sum of the steps run. */
    double simTime() {
        return simTime;
    }

    /** One step has run. */
    void stepped(double step) {
        simTime += step;
    }

    /**
     * Adds {@code realSeconds} to the time owed and returns how many steps to run now: as many as fit, at most
     * {@code maxSteps}; what is left over waits for the next frame, unless the cap was reached.
     */
    int stepsOwed(double realSeconds, double step, int maxSteps) {
        unsimulated += realSeconds;
        int steps = 0;
        while (unsimulated >= step - STEP_SLACK && steps < maxSteps) {
            unsimulated -= step;
            steps++;
        }
        if (steps == maxSteps) {
            unsimulated = 0;
        }
        return steps;
    }
}

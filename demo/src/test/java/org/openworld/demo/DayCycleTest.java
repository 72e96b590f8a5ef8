package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.openworld.engine.environment.TimeOfDay;

class DayCycleTest {

    private final DayCycle day = new DayCycle();

    @Test
    void scrubbingWrapsRoundMidnightAndKeepsTheSpeed() {
        TimeOfDay t = day.scrub(new TimeOfDay(23.9, 60), 1);
        // doubles: hours stepped by exact amounts and wrapped, equal to round-off
        assertEquals(0.15, t.hours(), 1e-9);
        assertEquals(60, t.daySpeed());
        assertEquals(23.9, day.scrub(t, -1).hours(), 1e-9);
    }

    @Test
    void pauseRemembersTheSpeedItResumesWith() {
        TimeOfDay running = new TimeOfDay(6, 240);
        TimeOfDay paused = day.togglePause(running);
        assertEquals(0, paused.daySpeed());
        assertEquals(6, paused.hours());
        assertEquals(240, day.togglePause(paused).daySpeed());
    }

    @Test
    void speedDoublesAndHalvesWithinItsRange() {
        assertEquals(120, day.changeSpeed(new TimeOfDay(12, 60), 2).daySpeed());
        assertEquals(DayCycle.MAX_SPEED, day.changeSpeed(new TimeOfDay(12, DayCycle.MAX_SPEED), 2).daySpeed());
        assertEquals(1, day.changeSpeed(new TimeOfDay(12, 1), 0.5).daySpeed());
        // paused: the clock stays stopped, the new speed waits for the resume
        TimeOfDay paused = day.changeSpeed(new TimeOfDay(12, 0), 2);
        assertEquals(0, paused.daySpeed());
        assertEquals(2 * DayCycle.RESUME_SPEED, day.togglePause(paused).daySpeed());
    }

    @Test
    void titleShowsTheClockAndTheSpeed() {
        assertEquals("18:45 ×60", DayCycle.describe(new TimeOfDay(18.75, 60)));
        assertEquals("06:05 paused", DayCycle.describe(new TimeOfDay(6 + 5 / 60.0, 0)));
    }
}

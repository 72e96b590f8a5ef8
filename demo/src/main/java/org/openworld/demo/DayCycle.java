package org.openworld.demo;

import org.openworld.engine.environment.TimeOfDay;

/**
 * The window's control of the day: pause and resume, scrub the clock, change its speed. Each key press gives the
 * new {@link TimeOfDay}; the engine advances it every fixed step at its speed.
 */
final class DayCycle {

    /** Fastest day cycle, simulated hours per real hour: a day in 10 seconds. */
    static final double MAX_SPEED = 8640;
    /** One press of [ or ] moves the clock this much, hours (a quarter of an hour). */
    static final double SCRUB_HOURS = 0.25;
    /** Speed a paused cycle resumes with when it had none, simulated hours per real hour. */
    static final double RESUME_SPEED = 60;

    private double pausedSpeed = RESUME_SPEED;

    /** T: stops the sun, or starts it again at the speed it had. */
    TimeOfDay togglePause(TimeOfDay t) {
        if (t.daySpeed() > 0) {
            pausedSpeed = t.daySpeed();
            return new TimeOfDay(t.hours(), 0);
        }
        return new TimeOfDay(t.hours(), pausedSpeed);
    }

    /** [ and ]: the clock {@code steps} quarter hours later (negative: earlier), wrapping round midnight. */
    TimeOfDay scrub(TimeOfDay t, int steps) {
        double h = ((t.hours() + steps * SCRUB_HOURS) % 24 + 24) % 24;
        return new TimeOfDay(h, t.daySpeed());
    }

    /** - and =: half or twice the speed ({@code factor} 0.5 or 2), within 1 .. {@link #MAX_SPEED} while running. */
    TimeOfDay changeSpeed(TimeOfDay t, double factor) {
        double speed = t.daySpeed() > 0 ? t.daySpeed() : pausedSpeed;
        speed = Math.max(1, Math.min(MAX_SPEED, speed * factor));
        if (t.daySpeed() > 0) {
            return new TimeOfDay(t.hours(), speed);
        }
        pausedSpeed = speed;
        return t;
    }

    /** What the title bar shows: the clock and the speed, e.g. {@code 18:45 ×60} or {@code 18:45 paused}. */
    static String describe(TimeOfDay t) {
        int minutes = (int) Math.floor(t.hours() * 60);
        String clock = String.format("%02d:%02d", minutes / 60 % 24, minutes % 60);
        return t.daySpeed() > 0 ? String.format("%s ×%.0f", clock, t.daySpeed()) : clock + " paused";
    }
}

package org.openworld.engine.environment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class TimeOfDayTest {
    // Tolerances here: doubles: hours from minutes and sums of steps, exact to round-off (1e-12, 1e-9 after sums)

    @Test
    void parsesHoursAndMinutes() {
        // doubles: hours from minutes / 60, exact to round-off (1e-12; 1e-9 after sums of steps)
        assertEquals(6.5, TimeOfDay.parseHours("06:30"), 1e-12);
        assertEquals(19.5, TimeOfDay.parseHours(" 19:30 "), 1e-12);
        assertEquals(0, TimeOfDay.parseHours("0:00"), 1e-12);
        assertEquals(23 + 59 / 60.0, TimeOfDay.parseHours("23:59"), 1e-12);
    }

    @Test
    void rejectsMalformedTimesSayingWhatIsExpected() {
        for (String bad : new String[] {"6.30", "630", "06:3", "noon", "", "-1:00"}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> TimeOfDay.parseHours(bad));
            assertTrue(e.getMessage().contains("'" + bad + "'") && e.getMessage().contains("HH:MM"), e.getMessage());
        }
    }

    @Test
    void rejectsHoursAndMinutesOutOfRange() {
        for (String bad : new String[] {"24:00", "12:60", "99:99"}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> TimeOfDay.parseHours(bad));
            assertTrue(e.getMessage().contains("'" + bad + "'") && e.getMessage().contains("0–23"), e.getMessage());
        }
    }

    @Test
    void advanceRunsAtDaySpeedAndWrapsPastMidnight() {
        // 60 simulated hours per real hour: one real minute is one hour of the day
        TimeOfDay evening = new TimeOfDay(23.5, 60);

        assertEquals(23.75, evening.advance(15).hours(), 1e-9);
        assertEquals(0.5, evening.advance(60).hours(), 1e-9);
        assertEquals(23.5, evening.advance(24 * 60).hours(), 1e-9, "a whole day comes back to the same time");
        assertEquals(60, evening.advance(60).daySpeed());
    }

    @Test
    void stoppedClockStaysAndBackwardsClockWrapsBelowZero() {
        assertEquals(10, new TimeOfDay(10, 0).advance(3600).hours());
        assertEquals(23.5, new TimeOfDay(0.5, -60).advance(60).hours(), 1e-9);
    }

    @Test
    void hoursOutsideTheDayAreRejected() {
        assertThrows(IllegalArgumentException.class, () -> new TimeOfDay(24, 0));
        assertThrows(IllegalArgumentException.class, () -> new TimeOfDay(-0.1, 0));
        assertThrows(IllegalArgumentException.class, () -> new TimeOfDay(Double.NaN, 0));
    }
}

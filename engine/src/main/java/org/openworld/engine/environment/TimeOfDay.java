package org.openworld.engine.environment;

/**
 * The clock of the day: hours since midnight, local solar time, and how fast it runs.
 *
 * @param hours    0 ≤ hours &lt; 24
 * @param daySpeed simulated hours per real (simulation) hour; 0 stops the sun
 */
public record TimeOfDay(double hours, double daySpeed) {

    public TimeOfDay {
        if (!(hours >= 0 && hours < 24)) {
            throw new IllegalArgumentException("time of day must be in [0, 24) hours, got " + hours);
        }
    }

    /** The clock after {@code seconds} of simulation. */
    public TimeOfDay advance(double seconds) {
        double h = (hours + seconds / 3600.0 * daySpeed) % 24.0;
        return new TimeOfDay(h < 0 ? h + 24 : h, daySpeed);
    }

    /** Parses {@code HH:MM}, e.g. {@code 06:30}; the error says what was expected. */
    public static double parseHours(String text) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("(\\d{1,2}):(\\d{2})").matcher(text.trim());
        if (!m.matches()) {
            throw new IllegalArgumentException("time '" + text + "': expected HH:MM, e.g. 14:30");
        }
        int h = Integer.parseInt(m.group(1));
        int min = Integer.parseInt(m.group(2));
        if (h > 23 || min > 59) {
            throw new IllegalArgumentException("time '" + text + "': hours 0–23 and minutes 0–59");
        }
        return h + min / 60.0;
    }
}

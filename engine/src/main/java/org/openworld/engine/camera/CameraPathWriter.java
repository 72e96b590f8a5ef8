package org.openworld.engine.camera;

import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.Locale;

/**
 * Writes a camera path in the format {@link CameraPathParser} reads, with a header that explains the columns, so a
 * recorded path can be read and edited by hand. Every value is printed to {@value #DECIMALS} decimals (1 ms, 1 mm,
 * 0.001°) without trailing zeros; parsing the text gives the path back within half of that.
 */
public final class CameraPathWriter {

    /** Decimals printed for every value: milliseconds, millimetres, thousandths of a degree. */
    static final int DECIMALS = 3;

    /** One key per line, columns padded so a file reads as a table. */
    private static final String ROW = "%-9s %-10s %-9s %-10s %-8s %-8s %s\n";

    private static final String HEADER = """
            # OpenWorld camera path (docs/camera-paths.md). One keyframe a line: time x y z yaw pitch fov
            #   time   seconds, increasing, keys at least 1 ms apart
            #   x y z  metres: x east, y up, z south (north is -z);
            #          y is above sea level (heights sea) or eye height above the ground (heights ground)
            #   yaw    degrees clockwise from north: 0 north, 90 east, 180 south, 270 west
            #   pitch  degrees, positive looking up, within [-89, 89]
            #   fov    vertical field of view, degrees, within (1, 179); optional, default 60
            # The camera follows a centripetal Catmull-Rom curve through the keys and takes the shorter turn in yaw.

            """;

    private CameraPathWriter() {
    }

    /**
     * The path as text: the header, its {@code heights} directive, then one line per key.
     *
     * @throws IllegalArgumentException if two key times are closer than the printed precision and would collide
     */
    public static String format(CameraPath path) {
        StringBuilder text = new StringBuilder(HEADER);
        text.append("heights ").append(path.heights().keyword()).append("\n\n");
        text.append(String.format(Locale.ROOT, ROW, "# time", "x", "y", "z", "yaw", "pitch", "fov"));
        String previousTime = null;
        for (Keyframe key : path.keys()) {
            String time = decimal(key.time());
            if (time.equals(previousTime)) {
                throw new IllegalArgumentException("two keys print as the same time " + time + " s");
            }
            previousTime = time;
            text.append(String.format(Locale.ROOT, ROW, time, decimal(key.x()),
                    decimal(key.y()), decimal(key.z()), decimal(key.yaw()), decimal(key.pitch()), decimal(key.fov())));
        }
        return text.toString();
    }

    /** {@code value} rounded to {@link #DECIMALS} decimals, e.g. 12.5 not 12.500, 3 not 3.000. */
    private static String decimal(double value) {
        return BigDecimal.valueOf(value).setScale(DECIMALS, RoundingMode.HALF_EVEN).stripTrailingZeros()
                .toPlainString();
    }
}

package org.openworld.engine.environment;

/**
 * Where snow lies on the ground, in metres: below {@code start} there is none, above {@code full} the ground is white,
 * and in between the chance rises (paper 2.2). Written by the terrain, which knows its relief, from the snow rule it
 * draws with (at init and every update); read by whatever grows or falls on the ground (trees stop below the snow).
 * It is the rule's line, not every pixel's: the drawn snow has a ragged fringe and slides off steep slopes. A world
 * without one has no snow line.
 *
 * @param start height where snow may begin, metres
 * @param full  height above which snow is certain, metres; at least {@code start}
 */
public record SnowLine(double start, double full) {

    public SnowLine {
        if (!Double.isFinite(start) || !Double.isFinite(full) || full < start) {
            throw new IllegalArgumentException("snow line from " + start + " m to " + full + " m: the heights must be "
                    + "numbers with the start at or below the full snow");
        }
    }

    /** How likely snow is at height {@code y}, metres: 0 below the start, 1 above the full line, linear between. */
    public double chanceAt(double y) {
        if (full == start) {
            return y >= full ? 1 : 0;
        }
        return Math.max(0, Math.min(1, (y - start) / (full - start)));
    }
}

package org.openworld.engine.sky;

import org.joml.Vector3f;

/**
 * The sun's direction from the time of day, the latitude and the season.
 *
 * <p>Elevation e at latitude φ, declination δ and hour angle H = 15° · (hours − 12):
 * {@code sin e = sin φ sin δ + cos φ cos δ cos H}; the east and north components follow from the same spherical
 * triangle. Local solar time: the sun stands highest, due south in the northern hemisphere, at 12:00.
 */
public final class SolarPosition {

    private SolarPosition() {
    }

    /** Unit vector towards the sun: east at morning, south at noon (northern latitudes), west at evening. */
    public static Vector3f direction(double hours, double latitudeDeg, double declinationDeg) {
        double phi = Math.toRadians(latitudeDeg);
        double delta = Math.toRadians(declinationDeg);
        double h = Math.toRadians(15 * (hours - 12));
        double up = Math.sin(phi) * Math.sin(delta) + Math.cos(phi) * Math.cos(delta) * Math.cos(h);
        double east = -Math.cos(delta) * Math.sin(h);
        double north = Math.cos(phi) * Math.sin(delta) - Math.sin(phi) * Math.cos(delta) * Math.cos(h);
        return new Vector3f((float) east, (float) up, (float) -north).normalize();
    }

    /** The time of day, hours, at which the sun stands at {@code elevationDeg} in the morning (or evening). */
    public static double hoursAtElevation(double elevationDeg, boolean morning, double latitudeDeg,
                                          double declinationDeg) {
        double phi = Math.toRadians(latitudeDeg);
        double delta = Math.toRadians(declinationDeg);
        double cosH = (Math.sin(Math.toRadians(elevationDeg)) - Math.sin(phi) * Math.sin(delta))
                / (Math.cos(phi) * Math.cos(delta));
        if (cosH < -1 || cosH > 1) {
            throw new IllegalArgumentException("the sun never reaches " + elevationDeg + "° at latitude "
                    + latitudeDeg + "° and declination " + declinationDeg + "°");
        }
        double hours = Math.toDegrees(Math.acos(cosH)) / 15;
        return morning ? 12 - hours : 12 + hours;
    }
}

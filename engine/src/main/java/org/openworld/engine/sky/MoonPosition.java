package org.openworld.engine.sky;

import org.joml.Matrix3f;
import org.joml.Vector3f;

/**
 * The moon and the stars on the sky of {@link SolarPosition}'s sun: a simple model, stated here, in the same local
 * solar time.
 *
 * <p><b>The celestial sphere.</b> The sun stands on the ecliptic, tilted ε = 23.44° to the equator, at the longitude λ☉
 * its declination gives, sin λ☉ = sin δ☉ / sin ε (taken in spring and summer, −90° ≤ λ☉ ≤ 90°). A point of right
 * ascension α and declination δ stands at the hour angle H = H☉ − (α − α☉), H☉ = 15° · (hours − 12), so it is
 * {@link SolarPosition#direction} of the clock shifted by (α − α☉) / 15° hours at declination δ. The same turn of
 * the sphere as one matrix ({@link #equatorialToLocal}) places the stars.
 *
 * <p><b>The moon</b> ({@code sky.moon-age}, days since new moon; the synodic month is {@value #SYNODIC_DAYS} days)
 * stands on the ecliptic (its 5.1° inclination neglected) at the elongation ψ = 360° · age / month east of the sun:
 * λ = λ☉ + ψ, sin δ = sin ε sin λ, tan α = cos ε tan λ. Its phase angle is i = 180° − ψ (the sun taken as far away),
 * the lit fraction of its disc (1 + cos i) / 2, and its light the magnitude law of Allen's Astrophysical Quantities,
 * V(i) = −12.73 + 0.026 |i| + 4·10⁻⁹ i⁴ (i in degrees), against the sun's V☉ = −26.74: the full moon gives
 * 10^(−0.4 (V − V☉)) = 2.5·10⁻⁶ of the sunlight, the quarter moon (i = 90°) a tenth of that. The age stays as set
 * while the clock runs (the moon keeps its place relative to the sun; in a real day it falls back 12° against it).
 */
public final class MoonPosition {

    /** Days from new moon to new moon. */
    public static final double SYNODIC_DAYS = 29.530589;
    /** The obliquity of the ecliptic, radians (23.44°). */
    static final double OBLIQUITY = Math.toRadians(23.44);
    /** The sun's apparent visual magnitude. */
    static final double SUN_MAGNITUDE = -26.74;
    /** The moon's angular radius, degrees (at its mean distance). */
    public static final double ANGULAR_RADIUS_DEG = 0.2590;

    private MoonPosition() {
    }

    /** The elongation ψ east of the sun at {@code ageDays}, radians, 0..2π. */
    public static double elongation(double ageDays) {
        double cycles = ageDays / SYNODIC_DAYS;
        return 2 * Math.PI * (cycles - Math.floor(cycles));
    }

    /** The phase angle i (sun–moon–earth), degrees, 0 (full) .. 180 (new). */
    public static double phaseAngleDeg(double ageDays) {
        return Math.abs(180 - Math.toDegrees(elongation(ageDays)));
    }

    /** The lit fraction of the disc, 0 (new) .. 1 (full). */
    public static double litFraction(double ageDays) {
        return (1 + Math.cos(Math.toRadians(phaseAngleDeg(ageDays)))) / 2;
    }

    /** The moon's irradiance above the air against the sun's (display units), from the magnitude law. */
    public static double irradiance(double ageDays) {
        double i = phaseAngleDeg(ageDays);
        double magnitude = -12.73 + 0.026 * i + 4e-9 * Math.pow(i, 4);
        return Math.pow(10, -0.4 * (magnitude - SUN_MAGNITUDE));
    }

    /** Unit vector towards the moon, world space. */
    public static Vector3f direction(double hours, double latitudeDeg, double declinationDeg, double ageDays) {
        double sun = sunLongitude(declinationDeg);
        double moon = sun + elongation(ageDays);
        return toLocal(rightAscension(moon) - rightAscension(sun), Math.asin(Math.sin(OBLIQUITY) * Math.sin(moon)),
                hours, latitudeDeg);
    }

    /**
     * The turn from equatorial axes (x towards right ascension 0, y towards 6 h, z towards the north celestial
     * pole) to the world's, at this clock, latitude and season.
     */
    public static Matrix3f equatorialToLocal(double hours, double latitudeDeg, double declinationDeg) {
        double sunRa = rightAscension(sunLongitude(declinationDeg));
        Vector3f x = toLocal(-sunRa, 0, hours, latitudeDeg);
        Vector3f y = toLocal(Math.PI / 2 - sunRa, 0, hours, latitudeDeg);
        Vector3f z = toLocal(0, Math.PI / 2, hours, latitudeDeg);
        return new Matrix3f(x, y, z);
    }

    /** The direction of a point {@code raFromSun} radians of right ascension east of the sun at declination dec. */
    private static Vector3f toLocal(double raFromSun, double dec, double hours, double latitudeDeg) {
        return SolarPosition.direction(hours - Math.toDegrees(raFromSun) / 15, latitudeDeg, Math.toDegrees(dec));
    }

    /** The sun's ecliptic longitude for its declination, radians, in −π/2..π/2 (spring and summer). */
    static double sunLongitude(double declinationDeg) {
        double s = Math.sin(Math.toRadians(declinationDeg)) / Math.sin(OBLIQUITY);
        return Math.asin(Math.max(-1, Math.min(1, s)));
    }

    /** Right ascension of the ecliptic point at longitude λ, radians: tan α = cos ε tan λ, in λ's quadrant. */
    static double rightAscension(double longitude) {
        return Math.atan2(Math.cos(OBLIQUITY) * Math.sin(longitude), Math.cos(longitude));
    }
}

package org.openworld.engine.sky;

/**
 * Everything the sky computes for one sun elevation and one eye altitude: the dome ({@link SkyView}), the air
 * between the eye and the ground ({@link AerialPerspective}) and the light they give ({@link SkyLight}). The sun's
 * azimuth does not enter: every table is laid out relative to it.
 *
 * @param atmosphere  the atmosphere's own tables these were computed from
 * @param sunElevation radians above the horizon
 * @param altitude    eye altitude above sea level, metres
 * @param buildMillis CPU time to compute the three, milliseconds
 */
public record SunTables(AtmosphereTables atmosphere, double sunElevation, double altitude, SkyView view,
                        AerialPerspective air, SkyLight light, double buildMillis) {

    /** Computes the tables for a sun elevation (radians) and an eye altitude (metres). */
    public static SunTables build(AtmosphereTables atmosphere, double sunElevation, double altitude) {
        long t0 = System.nanoTime();
        SkyView view = SkyView.build(atmosphere, sunElevation, altitude);
        AerialPerspective air = AerialPerspective.build(atmosphere, view, sunElevation, altitude);
        SkyLight light = SkyLight.of(atmosphere, view, sunElevation, altitude);
        return new SunTables(atmosphere, sunElevation, altitude, view, air, light, (System.nanoTime() - t0) / 1e6);
    }

    /**
     * Whether a sun at {@code elevation} and an eye at {@code altitude} differ enough from these tables' to be
     * worth new ones: the sky changes fastest with the sun near the horizon (colours turn within a degree), slowly
     * with it high, and with the eye's altitude over hundreds of metres (the air below it thins).
     */
    public boolean staleFor(AtmosphereSettings settings, double elevation, double altitude) {
        double lowSun = Math.toRadians(12);
        double step = Math.toRadians(Math.min(Math.abs(elevation), Math.abs(sunElevation)) < lowSun
                ? LOW_SUN_STEP_DEG : HIGH_SUN_STEP_DEG);
        return !settings.equals(atmosphere.settings())
                || Math.abs(elevation - sunElevation) > step
                || Math.abs(altitude - this.altitude) > ALTITUDE_STEP * Math.max(1, this.altitude / 1000);
    }

    /** Sun elevation change worth new tables with the sun within 12° of the horizon, degrees. */
    static final double LOW_SUN_STEP_DEG = 0.25;
    /** Sun elevation change worth new tables with the sun higher, degrees. */
    static final double HIGH_SUN_STEP_DEG = 1.0;
    /** Eye altitude change worth new tables per kilometre of altitude (at least 1 km), metres. */
    static final double ALTITUDE_STEP = 100;
}

package org.openworld.engine.sky;

import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * The sky's radiance in one world direction computed directly, without the {@link SkyView} table: the CPU reference
 * that rendered skies are compared with. It runs the same {@link SkyIntegrator#dome} as a SkyView texel, so the two
 * agree to float rounding wherever the view direction falls on a texel.
 */
public final class SkyReference {

    private SkyReference() {
    }

    /**
     * π·L / E_sun as linear sRGB for a view direction and a direction toward the sun (world space, Y up, any
     * length); only the elevations and the angle between the two azimuths matter.
     */
    public static Vector3d radiance(AtmosphereTables t, Vector3dc viewDir, Vector3dc sunDir, double cameraAltitudeM) {
        Vector3d view = new Vector3d(viewDir).normalize();
        Vector3d sun = new Vector3d(sunDir).normalize();
        double elevation = Math.asin(TransmittanceTable.clamp(view.y, -1, 1));
        double sunElevation = Math.asin(TransmittanceTable.clamp(sun.y, -1, 1));
        double[] spectral = new SkyIntegrator(t).dome(cameraAltitudeM, azimuthBetween(view, sun), elevation,
                sunElevation, new double[t.spectrum().count()]);
        return t.spectrum().toDisplayRgb(spectral, new Vector3d());
    }

    /**
     * Luminance of the zenith, π·L / E_sun weighted 0.2126, 0.7152, 0.0722 over linear sRGB (Rec. 709's Y), for a
     * sun at {@code sunElevationRad}: how bright the sky overhead is, in the display units the scene exposes.
     */
    public static double zenithLuminance(AtmosphereTables t, double sunElevationRad, double cameraAltitudeM) {
        Vector3d up = radiance(t, new Vector3d(0, 1, 0),
                new Vector3d(Math.cos(sunElevationRad), Math.sin(sunElevationRad), 0), cameraAltitudeM);
        return 0.2126 * up.x + 0.7152 * up.y + 0.0722 * up.z;
    }

    /**
     * The zenith's luminance as a picture shows it: {@link #zenithLuminance} times the exposure the sky system would
     * use for that sun ({@code sky.auto-exposure}: adapted to the light of the moment, or noon's; times the
     * compensation {@code sky.exposure}). A sky darker than another in the scene can show brighter once exposed.
     */
    public static double displayedZenith(AtmosphereTables t, SkySettings sky, double sunElevationRad,
                                         double cameraAltitudeM) {
        SkyLight light = SunTables.build(t, sunElevationRad, cameraAltitudeM).light();
        Vector3d ground = light.sun().mul(Math.max(Math.sin(sunElevationRad), 0)).add(light.ambient());
        return zenithLuminance(t, sunElevationRad, cameraAltitudeM) * SkySystem.exposure(sky, ground).scale();
    }

    /** Angle between the horizontal projections of two directions, [0, π]; 0 when either is vertical. */
    static double azimuthBetween(Vector3dc a, Vector3dc b) {
        double dot = a.x() * b.x() + a.z() * b.z();
        double cross = a.x() * b.z() - a.z() * b.x();
        if (Math.hypot(a.x(), a.z()) < 1e-12 || Math.hypot(b.x(), b.z()) < 1e-12) {
            return 0;
        }
        return Math.atan2(Math.abs(cross), dot);
    }
}

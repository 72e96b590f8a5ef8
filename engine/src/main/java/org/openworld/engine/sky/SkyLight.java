package org.openworld.engine.sky;

import org.joml.Vector3d;

/**
 * The light the sky puts on the scene for one sun position, in display units (E / E_sun, linear sRGB): the direct
 * sun and the sky's ambient irradiance.
 * <ul>
 * <li>{@link #sun()}: T(r, μ_s)·1 through the {@link TransmittanceTable}, times the fraction of the solar disc (radius
 *     {@value #SUN_ANGULAR_RADIUS_DEG}°) above the eye's horizon, so the sun fades as it sets instead of switching
 *     off.</li>
 * <li>{@link #ambient()}: E = ∫_{upper hemisphere} L cosθ dω from the {@link SkyView} table, which stores P = π·L, so
 *     E = 2 ∫₀^π dφ ∫₀^{π/2} (P/π) sin e cos e de (the sky is symmetric about the sun's plane), by the midpoint rule
 *     on {@value #AMBIENT_AZIMUTHS} × {@value #AMBIENT_ELEVATIONS} directions. A uniform sky P = 1 gives E = 1.</li>
 * </ul>
 */
public final class SkyLight {

    /** Angular radius of the solar disc, degrees (mean, seen from Earth). */
    public static final double SUN_ANGULAR_RADIUS_DEG = 0.2666;
    /** Midpoint-rule directions over the azimuth 0..π for the ambient integral. */
    private static final int AMBIENT_AZIMUTHS = 32;
    /** Midpoint-rule directions over the elevation 0..π/2: sin e cos e is smooth, 16 are within 0.2 %. */
    private static final int AMBIENT_ELEVATIONS = 16;

    private final Vector3d sun;
    private final Vector3d ambient;

    private SkyLight(Vector3d sun, Vector3d ambient) {
        this.sun = sun;
        this.ambient = ambient;
    }

    /** Sun and ambient light for a sun at {@code sunElevationRad}, from a SkyView built for that sun. */
    public static SkyLight of(AtmosphereTables t, SkyView view, double sunElevationRad, double cameraAltitudeM) {
        return new SkyLight(sunlight(t, sunElevationRad, cameraAltitudeM), ambient(view));
    }

    /** Direct sunlight at the eye, E / E_sun as linear sRGB (a copy). */
    public Vector3d sun() {
        return new Vector3d(sun);
    }

    /** Sky irradiance on an upward-facing surface, E / E_sun as linear sRGB (a copy). */
    public Vector3d ambient() {
        return new Vector3d(ambient);
    }

    private static Vector3d sunlight(AtmosphereTables t, double sunElevationRad, double cameraAltitudeM) {
        double r = SkyIntegrator.eyeRadius(cameraAltitudeM);
        double horizonCos = -Math.sqrt(Math.max(1 - Math.pow(Atmosphere.BOTTOM_RADIUS / r, 2), 0));
        double horizonElevation = Math.asin(horizonCos);
        double visible = discFractionAbove((sunElevationRad - horizonElevation)
                / Math.toRadians(SUN_ANGULAR_RADIUS_DEG));
        if (visible <= 0) {
            return new Vector3d();
        }
        // A disc partly above the horizon is lit through the grazing ray just above it.
        double mu = Math.max(Math.sin(sunElevationRad), horizonCos + 1e-6);
        double[] spectral = t.transmittance().transmittance(r, mu, new double[t.spectrum().count()]);
        for (int i = 0; i < spectral.length; i++) {
            spectral[i] *= visible;
        }
        return t.spectrum().toDisplayRgb(spectral, new Vector3d());
    }

    /**
     * Fraction of a disc above a line at signed distance x disc radii below its centre (x = 1: the disc's lowest
     * point on the line): 1 − (acos x − x√(1 − x²))/π, clamped to 0 and 1 outside [−1, 1].
     */
    static double discFractionAbove(double x) {
        if (x >= 1) {
            return 1;
        }
        if (x <= -1) {
            return 0;
        }
        return 1 - (Math.acos(x) - x * Math.sqrt(1 - x * x)) / Math.PI;
    }

    private static Vector3d ambient(SkyView view) {
        Vector3d sum = new Vector3d();
        Vector3d p = new Vector3d();
        double dPhi = Math.PI / AMBIENT_AZIMUTHS;
        double dE = Math.PI / 2 / AMBIENT_ELEVATIONS;
        for (int j = 0; j < AMBIENT_ELEVATIONS; j++) {
            double e = (j + 0.5) * dE;
            double weight = 2 * Math.sin(e) * Math.cos(e) * dE * dPhi / Math.PI;
            for (int i = 0; i < AMBIENT_AZIMUTHS; i++) {
                sum.fma(weight, view.sample((i + 0.5) * dPhi, e, p));
            }
        }
        return sum;
    }
}

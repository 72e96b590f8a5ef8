package org.openworld.engine.sky;

import org.joml.Vector3d;
import org.joml.Vector3fc;
import org.openworld.engine.environment.SkyIrradiance;
import org.openworld.engine.environment.Sun;

/**
 * The light the sky puts on the scene for one sun position, in display units (E / E_sun, linear sRGB): the direct
 * sun and the sky's ambient irradiance.
 * <ul>
 * <li>{@link #sun()}: T(r, μ_s)·1 through the {@link TransmittanceTable}, times the fraction of the solar disc (radius
 *     {@value Sun#ANGULAR_RADIUS_DEG}°) above the eye's horizon, so the sun fades as it sets instead of switching
 *     off.</li>
 * <li>{@link #ambient()}: E = ∫_{upper hemisphere} L cosθ dω from the {@link SkyView} table, which stores P = π·L, so
 *     E = 2 ∫₀^π dφ ∫₀^{π/2} (P/π) sin e cos e de (the sky is symmetric about the sun's plane), by the midpoint rule
 *     on {@value #AMBIENT_AZIMUTHS} × {@value #AMBIENT_ELEVATIONS} directions. A uniform sky P = 1 gives E = 1.</li>
 * <li>{@link #irradiance}: the same sky for any normal, as spherical harmonics in the world's axes (the table turned
 *     to the sun's azimuth), with the ground around as a uniform lower hemisphere of radiance
 *     albedo · (sun on level ground + ambient) / π: one bounce of the light that reaches the ground.</li>
 * </ul>
 */
public final class SkyLight {

    /** Midpoint-rule directions over the azimuth 0..π for the ambient integral. */
    private static final int AMBIENT_AZIMUTHS = 32;
    /** Midpoint-rule directions over the elevation 0..π/2: sin e cos e is smooth, 16 are within 0.2 %. */
    private static final int AMBIENT_ELEVATIONS = 16;

    /** Midpoint-rule directions over the azimuth 0..π (each used on both sides of the sun) for the harmonics. */
    private static final int IRRADIANCE_AZIMUTHS = 48;
    /** Midpoint-rule directions over the elevation 0..π/2 for the harmonics. */
    private static final int IRRADIANCE_ELEVATIONS = 24;

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

    /**
     * The sky of {@code view} around a sun towards {@code toSun} (world space) and the ground lit by {@code light},
     * of reflectance {@code groundAlbedo}, as {@link SkyIrradiance}: the upper hemisphere by the midpoint rule on
     * {@value #IRRADIANCE_AZIMUTHS} × {@value #IRRADIANCE_ELEVATIONS} directions (each azimuth from the sun's plane
     * counted on both sides of it), the ground in closed form, and the light of the terrain where it hides the sky
     * (SkyIrradiance#hiddenBy), and the night's light: the moon as one more direction, the night sky as a uniform
     * upper hemisphere, both lighting the ground too. A few thousand table reads: run when the sun moved.
     */
    public static SkyIrradiance irradiance(SkyView view, SkyLight light, Vector3fc toSun, double groundAlbedo,
                                           NightLight night) {
        Vector3d toward = new Vector3d(toSun.x(), 0, toSun.z());
        if (toward.lengthSquared() < 1e-12) {
            toward.set(1, 0, 0); // the sun overhead: the sky is the same all round, any azimuth will do
        }
        toward.normalize();
        Vector3d side = new Vector3d(-toward.z, 0, toward.x);
        SkyIrradiance sky = new SkyIrradiance();
        Vector3d p = new Vector3d();
        Vector3d d = new Vector3d();
        double dPhi = Math.PI / IRRADIANCE_AZIMUTHS;
        double dE = Math.PI / 2 / IRRADIANCE_ELEVATIONS;
        for (int j = 0; j < IRRADIANCE_ELEVATIONS; j++) {
            double e = (j + 0.5) * dE;
            double dOmega = Math.cos(e) * dE * dPhi;
            for (int i = 0; i < IRRADIANCE_AZIMUTHS; i++) {
                double phi = (i + 0.5) * dPhi;
                view.sample(phi, e, p).div(Math.PI); // the table holds π·L
                for (int sign = -1; sign <= 1; sign += 2) {
                    d.set(toward).mul(Math.cos(phi)).fma(sign * Math.sin(phi), side).mul(Math.cos(e));
                    d.y = Math.sin(e);
                    sky.add(d, p, dOmega);
                }
            }
        }
        if (night.moonDirection().y() > 0) {
            sky.add(new Vector3d(night.moonDirection()), night.moon(), 1); // a direction: L dω is its irradiance
        }
        sky.addUpperHemisphere(new Vector3d(night.sky()).div(Math.PI));
        Vector3d sunOnGround = light.sun().mul(Math.max(toSun.y(), 0)).add(night.onLevelGround());
        Vector3d ground = new Vector3d(sunOnGround).add(light.ambient()).mul(groundAlbedo / Math.PI);
        // the terrain that hides the sky from a place faces that place; seen from all round, half of it faces the
        // sun: so its light is the open ground's with half the sun's (HorizonSearch, the hidden share)
        Vector3d hidden = sunOnGround.mul(0.5).add(light.ambient()).mul(groundAlbedo);
        return sky.addLowerHemisphere(ground).hiddenBy(hidden);
    }

    /**
     * Light from a body of the sun's size at {@code sunElevationRad} through the air to the eye, for a body of the
     * sun's light above the air: the transmittance times the part of its disc above the horizon.
     */
    static Vector3d sunlight(AtmosphereTables t, double sunElevationRad, double cameraAltitudeM) {
        double r = SkyIntegrator.eyeRadius(cameraAltitudeM);
        double horizonCos = -Math.sqrt(Math.max(1 - Math.pow(Atmosphere.BOTTOM_RADIUS / r, 2), 0));
        double horizonElevation = Math.asin(horizonCos);
        double visible = discFractionAbove((sunElevationRad - horizonElevation)
                / Math.toRadians(Sun.ANGULAR_RADIUS_DEG));
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

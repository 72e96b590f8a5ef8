package org.openworld.engine.environment;

import java.util.List;
import org.joml.Vector3f;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.core.World;
import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;
import org.openworld.engine.settings.Settings;

/**
 * A first-order sun for worlds without a sky model: solar position from the time of day, and sunlight reddened by
 * the air mass it crosses. The sky system replaces this with transmittance from its scattering tables.
 *
 * <p>Solar elevation e and azimuth a at latitude φ, declination δ and hour angle H = 15° · (hours − 12):
 * {@code sin e = sin φ sin δ + cos φ cos δ cos H}. Air mass m by Kasten and Young (1989),
 * {@code m = 1 / (sin e + 0.50572 (e + 6.07995°)^−1.6364)}, and per-channel extinction
 * {@code T = exp(−τ m)} with a zenith optical depth τ that is largest for blue (Rayleigh's λ⁻⁴).
 */
public final class DaylightSystem implements EngineSystem {

    /**
     * @param latitude    observer latitude, degrees north
     * @param declination solar declination, degrees (about +23 in June, −23 in December)
     */
    public record DaylightSettings(
            @Setting(doc = "observer latitude", unit = "deg", min = -89, max = 89) double latitude,
            @Setting(doc = "solar declination (season)", unit = "deg", min = -23.44, max = 23.44) double declination,
            @Setting(doc = "fog extinction at sea level", unit = "1/m", min = 0, max = 0.01) double fogDensity,
            @Setting(doc = "fog density falls by e every 1/x metres of height", unit = "1/m", min = 0, max = 0.1)
            double fogHeightFalloff) {

        public static final DaylightSettings DEFAULTS = new DaylightSettings(46, 10, 0.00012, 0.0012);
    }

    public static final SettingsGroup<DaylightSettings> SETTINGS =
            SettingsGroup.of("daylight", DaylightSettings.class, DaylightSettings.DEFAULTS);

    /** Zenith optical depth per channel (R, G, B): Rayleigh plus a little haze; blue is scattered most. */
    private static final Vector3f ZENITH_OPTICAL_DEPTH = new Vector3f(0.10f, 0.20f, 0.42f);

    @Override
    public SystemSpec spec() {
        return SystemSpec.named("daylight").reads(TimeOfDay.class, Settings.class).writes(Sun.class, Fog.class);
    }

    @Override
    public List<SettingsGroup<?>> settings() {
        return List.of(SETTINGS);
    }

    @Override
    public void init(EngineContext context) {
        update(context.world(), 0);
    }

    @Override
    public void update(World world, double step) {
        DaylightSettings s = world.resource(Settings.class).get(DaylightSettings.class);
        Vector3f toSun = sunDirection(world.resource(TimeOfDay.class).hours(), s.latitude(), s.declination());
        double elevation = Math.toDegrees(Math.asin(toSun.y));
        Vector3f light = transmittance(elevation);
        // Sky light: a share of the scattered light, fading out in the night.
        float day = (float) smoothstep(-6, 10, elevation);
        Vector3f ambient = new Vector3f(0.30f, 0.38f, 0.50f).mul(0.05f + 0.95f * day);
        world.setResource(new Sun(toSun, light, ambient));
        Vector3f fogColor = new Vector3f(0.62f, 0.70f, 0.80f).mul(light.length() / 1.7f * day + 0.03f);
        world.setResource(new Fog(fogColor, (float) s.fogDensity(), (float) s.fogHeightFalloff()));
    }

    /** Unit vector towards the sun: east at morning, south at noon (northern latitudes), west at evening. */
    public static Vector3f sunDirection(double hours, double latitudeDeg, double declinationDeg) {
        double phi = Math.toRadians(latitudeDeg);
        double delta = Math.toRadians(declinationDeg);
        double h = Math.toRadians(15 * (hours - 12));
        // Local east-north-up components of the direction to the sun.
        double up = Math.sin(phi) * Math.sin(delta) + Math.cos(phi) * Math.cos(delta) * Math.cos(h);
        double east = -Math.cos(delta) * Math.sin(h);
        double north = Math.cos(phi) * Math.sin(delta) - Math.sin(phi) * Math.cos(delta) * Math.cos(h);
        return new Vector3f((float) east, (float) up, (float) -north).normalize();
    }

    /** Sunlight at the ground for a sun at {@code elevationDeg}, linear RGB, zero below the horizon. */
    public static Vector3f transmittance(double elevationDeg) {
        if (elevationDeg <= -1) {
            return new Vector3f();
        }
        double e = Math.max(elevationDeg, 0);
        double airMass = 1 / (Math.sin(Math.toRadians(e)) + 0.50572 * Math.pow(e + 6.07995, -1.6364));
        return new Vector3f(
                (float) Math.exp(-ZENITH_OPTICAL_DEPTH.x * airMass),
                (float) Math.exp(-ZENITH_OPTICAL_DEPTH.y * airMass),
                (float) Math.exp(-ZENITH_OPTICAL_DEPTH.z * airMass)).mul((float) smoothstep(-1, 1, elevationDeg) * 1.3f);
    }

    private static double smoothstep(double edge0, double edge1, double x) {
        double t = Math.min(1, Math.max(0, (x - edge0) / (edge1 - edge0)));
        return t * t * (3 - 2 * t);
    }
}

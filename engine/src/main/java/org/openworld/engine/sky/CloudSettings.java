package org.openworld.engine.sky;

import org.joml.Vector2d;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Settings of the cloud layer, keys {@code clouds.*}: the density field (paper 2.1, a 3D DFT over two axes of space
 * and one of time, {@link CloudField}), how much of the sky it covers, how it moves, and how the sky dome maps it
 * (paper 2.3, figure 5 a–d, {@code shaders/sky/clouds.glsl}).
 *
 * @param mode          what draws the clouds: the paper's flat layer on the sky dome, or a volume ray-marched between
 *                      two altitudes ({@code org.openworld.engine.sky.clouds})
 * @param mapping       the sky-dome mapping, how a view direction finds its point in the field: spherical,
 *                      spherical-fog, perspective or perspective-fog, the four variants of figure 5
 * @param cover         fraction of the field's samples that are cloud: the density threshold is the field's
 *                      (1 − cover) quantile ({@link CloudField#coverageThreshold}); 0 is a clear sky, 1 overcast
 * @param altitude      height of the cloud plane above the eye, for the perspective mappings
 * @param tileSize      the field's period on the cloud plane: one texture repeat, metres across
 * @param beta          spectral exponent of the field's <em>power</em>, P(f) ∝ 1/f^β, so the amplitude falls as
 *                      1/f^(β/2). β = 2, the default, is the paper's amplitude 1/ω. (The terrain's
 *                      {@code terrain.beta} is an <em>amplitude</em> exponent; this one follows the usual convention
 *                      for noise, where β = 2 is "brown" and the measured log-log slope of the power is −β.)
 * @param period        time after which the field's evolution repeats: the frames span one period and loop
 * @param windSpeed     speed at which the wind carries the field over the cloud plane
 * @param windDirection direction the wind blows <em>towards</em>, degrees clockwise from north seen from above
 *                      (the docs/design.md yaw convention: 0 north, 90 east)
 * @param resolution    samples of the field per side of a tile, a power of two
 * @param frames        samples of the field over one period, a power of two; the shader blends neighbouring frames
 * @param base          altitude of the volume's base above sea level (volumetric mode)
 * @param thickness     height from the volume's base to its top (volumetric mode)
 * @param type          the clouds' height profile, 0 stratus (a thin sheet low in the layer) to 1 cumulus (rising
 *                      through the whole layer): {@code clouds.CloudOptics#heightProfile}
 * @param horizonFog    fog distance on the cloud layer for the fog mappings: the e-folding distance of the horizon
 *                      fog along the cloud plane, in tiles: at a distance of
 *                      {@code horizonFog · tileSize} the fog variants keep 1/e of a cloud's opacity and colour. One
 *                      tile (the default) hides the repeats of figure 5c, which show from a few tiles away
 */
public record CloudSettings(
        @Setting(doc = "what draws the clouds: LAYER (a flat layer on the dome, the paper's) or VOLUMETRIC (ray-marched)")
        Mode mode,
        @Setting(doc = "sky-dome mapping: spherical, spherical-fog, perspective or perspective-fog (figure 5 a-d)")
        Mapping mapping,
        @Setting(doc = "fraction of the sky covered by cloud", min = 0, max = 1) double cover,
        @Setting(doc = "height of the cloud layer above the eye", unit = "m", min = 500, max = 10000) double altitude,
        @Setting(doc = "period of the cloud field on the layer", unit = "m", min = 1000, max = 100000) double tileSize,
        @Setting(doc = "spectral exponent: power ~ 1/frequency^beta (2 = amplitude 1/f, the paper's)", min = 0.5,
                max = 4, atStart = true) double beta,
        @Setting(doc = "loop time of the clouds' evolution", unit = "s", min = 10, max = 3600) double period,
        @Setting(doc = "wind speed on the cloud layer", unit = "m/s", min = 0, max = 50) double windSpeed,
        @Setting(doc = "direction the wind blows towards, clockwise from north", unit = "deg", min = 0, max = 360)
        double windDirection,
        @Setting(doc = "field samples per tile side, a power of two", min = 32, max = 256, atStart = true)
        int resolution,
        @Setting(doc = "field samples over one period, a power of two", min = 4, max = 64, atStart = true) int frames,
        @Setting(doc = "VOLUMETRIC: altitude of the cloud base above sea level", unit = "m", min = 200, max = 8000)
        double base,
        @Setting(doc = "VOLUMETRIC: height from the cloud base to the top", unit = "m", min = 100, max = 6000)
        double thickness,
        @Setting(doc = "VOLUMETRIC: height profile, 0 stratus .. 1 cumulus", min = 0, max = 1) double type,
        @Setting(doc = "fog distance on the layer for the *_FOG mappings", unit = "tiles", min = 0.05, max = 4)
        double horizonFog) {

    /** What draws the clouds. */
    public enum Mode {
        /** The paper's: the field as a flat layer on the sky dome, through one of the {@link Mapping}s. */
        LAYER,
        /** A volume between {@code base} and {@code base + thickness}, ray-marched ({@code engine.clouds}). */
        VOLUMETRIC
    }

    /** The four ways of figure 5 to put the field on the sky dome; the shader's mode number is the ordinal. */
    public enum Mapping {
        /** Figure 5a: (azimuth / 2π, elevation / (π/2)) as texture coordinates; the horizon is squeezed. */
        SPHERICAL,
        /** Figure 5b: the spherical mapping with a fog that hides the horizon. */
        SPHERICAL_FOG,
        /** Figure 5c: the ray meets a plane at {@code altitude}; open, but the tile repeats toward the horizon. */
        PERSPECTIVE,
        /** Figure 5d: the perspective mapping with a fog that fades the far repeats into the horizon. */
        PERSPECTIVE_FOG
    }

    public static final CloudSettings DEFAULTS = new CloudSettings(
            Mode.LAYER, // the volume costs more than the budget allows on the 2-core llvmpipe (docs/sky.md)
            Mapping.PERSPECTIVE_FOG, // the paper's final choice, figure 5d
            0.45,    // a bit under half the sky: broken cumulus with blue between
            2500,    // m: a low cumulus base over the eye
            12000,   // m: a tile about five times the altitude, so the first repeat is 12 km off, well down the sky
            2,       // power 1/f², amplitude 1/f: the paper's spectrum
            240,     // s: four minutes before the evolution repeats, long enough not to notice
            8,       // m/s: a fresh breeze at cloud height, about 30 km/h
            60,      // deg: towards east-north-east
            128,     // samples: 94 m per texel on the default 12 km tile, 1 MiB of half floats with 16 frames
            16,      // frames: 15 s apart over the 240 s loop, blended linearly
            1800,    // m: a fair-weather cumulus base over valleys a few hundred metres up
            1500,    // m: cumulus a kilometre and a half tall, with room for the towers
            0.8,     // mostly cumulus: rounded tops over flat, darker bases
            1);      // tiles: the fog's e-folding distance is one tile, hiding the repeats

    /** Metres: the layer the reflections show stays this far over an eye in or above the volume (the setting's least). */
    static final double MIN_LAYER_ABOVE_EYE = 500;

    public static final SettingsGroup<CloudSettings> SETTINGS =
            SettingsGroup.of("clouds", CloudSettings.class, DEFAULTS);

    /** Checks what single ranges cannot: the sample counts are powers of two, the mapping is given. */
    public CloudSettings {
        if (mode == null || mapping == null) {
            throw new IllegalArgumentException("the cloud mode or mapping is missing");
        }
        if (Integer.bitCount(resolution) != 1) {
            throw new IllegalArgumentException("the cloud resolution must be a power of two (32, 64, 128, 256), got "
                    + resolution);
        }
        if (Integer.bitCount(frames) != 1) {
            throw new IllegalArgumentException("the cloud frames must be a power of two (4, 8, ... 64), got " + frames);
        }
    }

    /**
     * The wind's displacement of the field after {@code seconds}, metres (x east, y south on the plane, i.e. world
     * x and z), each axis wrapped into [0, tileSize) since the field repeats by the tile.
     */
    public Vector2d windOffset(double seconds, Vector2d dest) {
        Vector3f velocity = windVelocity(new Vector3f());
        return dest.set(wrap(velocity.x * seconds, tileSize), wrap(velocity.z * seconds, tileSize));
    }

    /** The wind as a world-space velocity, m/s: horizontal, {@code windSpeed} long, towards {@code windDirection}. */
    public Vector3f windVelocity(Vector3f dest) {
        double yaw = Math.toRadians(windDirection);
        // yaw clockwise from north (−Z): east is +X, so the direction is (sin yaw, −cos yaw) in (x, z)
        return dest.set((float) (windSpeed * Math.sin(yaw)), 0, (float) (-windSpeed * Math.cos(yaw)));
    }

    /**
     * The {@code cloudParams} uniform of {@code sky/clouds.glsl}: x the density threshold (from
     * {@link CloudField#coverageThreshold}), y the altitude, z the tile size, w the fog distance, all metres but x.
     */
    public Vector4f cloudParams(float threshold, Vector4f dest) {
        return dest.set(threshold, (float) altitude, (float) tileSize, (float) (horizonFog * tileSize));
    }

    /**
     * {@link #cloudParams(float, Vector4f)} for an eye {@code eyeAltitude} metres above sea level: in the volumetric
     * mode the layer (which the water's reflection and the environment map still show) lies at the volume's middle
     * height, at least {@link #MIN_LAYER_ABOVE_EYE} above the eye.
     */
    public Vector4f cloudParams(float threshold, double eyeAltitude, Vector4f dest) {
        cloudParams(threshold, dest);
        if (mode == Mode.VOLUMETRIC) {
            dest.y = (float) Math.max(base + thickness / 2 - eyeAltitude, MIN_LAYER_ABOVE_EYE);
        }
        return dest;
    }

    /**
     * The {@code cloudMotion} uniform of {@code sky/clouds.glsl} at {@code seconds}: xy the wind offset
     * ({@link #windOffset}, metres), z the time phase in [0, 1) (seconds / period, wrapped), w the mapping's number
     * ({@link Mapping#ordinal()}).
     */
    public Vector4f cloudMotion(double seconds, Vector4f dest) {
        Vector2d wind = windOffset(seconds, new Vector2d());
        double phase = wrap(seconds / period, 1);
        return dest.set((float) wind.x, (float) wind.y, (float) phase, mapping.ordinal());
    }

    /** x wrapped into [0, period), also for negative x. */
    private static double wrap(double x, double period) {
        double w = x - period * Math.floor(x / period);
        return w < period ? w : 0; // x just below a multiple of the period can round up to it
    }
}

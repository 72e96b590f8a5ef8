package org.openworld.engine.particles;

import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Settings of the snowfall, keys {@code particles.*} (paper section 4, figure 14).
 *
 * @param count      snowflakes in the volume around the eye; changing it rebuilds the buffers once
 * @param fallSpeed  speed at which a flake falls through still air, m/s: the terminal velocity g / k of the update
 *                   rule (real flakes fall at 0.5–1.5 m/s)
 * @param drag       k, the rate at which a flake takes on the air's velocity, 1/s: after a gust it is 1/e of the
 *                   way off after 1/k seconds. A real flake's is about 2g / v ≈ 20/s (quadratic drag linearised
 *                   about its fall speed); the default 2/s lets the random pushes make slow swirls, not a jitter
 * @param turbulence RMS speed of a flake's random motion about the mean flow, m/s: the Brownian term's strength is
 *                   chosen so that the velocity's spread settles at this (an Ornstein–Uhlenbeck process)
 * @param size       a flake's diameter, metres (aggregates of crystals are 1–3 cm)
 * @param volume     side of the cube around the eye that the flakes fill and wrap around, metres
 * @param windShare  the share of the cloud layer's wind that blows where the snow falls: a logarithmic wind profile
 *                   gives about 0.4 at 10 m above the ground under a layer 2.5 km up
 */
public record ParticleSettings(
        @Setting(doc = "number of snowflakes", min = 1, max = 4_000_000) int count,
        @Setting(doc = "terminal fall speed in still air", unit = "m/s", min = 0.05, max = 20) double fallSpeed,
        @Setting(doc = "rate at which a flake takes on the air's velocity", unit = "1/s", min = 0.1, max = 50)
        double drag,
        @Setting(doc = "RMS speed of the random (Brownian) motion", unit = "m/s", min = 0, max = 5) double turbulence,
        @Setting(doc = "flake diameter", unit = "m", min = 0.002, max = 1) double size,
        @Setting(doc = "side of the cube of snow around the eye", unit = "m", min = 5, max = 1000) double volume,
        @Setting(doc = "share of the cloud layer's wind felt by the snow", min = 0, max = 1) double windShare) {

    public static final ParticleSettings DEFAULTS = new ParticleSettings(
            100_000,  // a dense fall on screen at the default budget; 1 M runs too
            1.0,      // m/s: a typical aggregate flake
            2.0,      // 1/s: half a second to follow the air
            0.3,      // m/s: a gentle flutter, a third of the fall speed
            0.03,     // m: a 3 cm aggregate, a large wet flake
            30,       // m: flakes fade out from 9 m to the 15 m edge, where a 3 cm flake is a 1080p pixel across
            0.3);     // a 2.4 m/s breeze under the default 8 m/s cloud wind

    public static final SettingsGroup<ParticleSettings> SETTINGS =
            SettingsGroup.of("particles", ParticleSettings.class, DEFAULTS);

    /** g of the update rule, m/s²: the steady downward pull that drag balances at the fall speed (g = k · v). */
    public double gravity() {
        return drag * fallSpeed;
    }

    /**
     * σ of the update rule, m/s^1.5: the Brownian term adds σ · √dt · N(0, 1) to each velocity component per step,
     * and with drag k the velocity's spread settles at σ / √(2k) (for small steps), which is {@link #turbulence}.
     */
    public double brownian() {
        return turbulence * Math.sqrt(2 * drag);
    }
}

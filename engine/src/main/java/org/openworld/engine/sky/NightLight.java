package org.openworld.engine.sky;

import org.joml.Vector3d;
import org.joml.Vector3f;
import org.joml.Vector3fc;

/**
 * The light of the night, added to the sky's: the moon's, and the glow of a moonless sky. Display units (1 = the sun
 * above the air), linear sRGB.
 * <ul>
 * <li>The night sky: the airglow of the upper air, the zodiacal light and the stars too faint to see one by one make
 *     a clear moonless sky about 21.6 magnitudes per square arcsecond (V) away from the Milky Way (Leinert et al.
 *     1998, "The 1997 reference of diffuse night sky brightness"): L = 10.8·10⁴ · 10^(−0.4 · 21.6) = 2.5·10⁻⁴
 *     cd/m², so π·L / {@link Adaptation#SUN_LUX} = {@value #SKY} in display units, grey, over the whole upper
 *     hemisphere: 8·10⁻⁴ lux on the ground, the "starlight" of the textbooks.</li>
 * <li>The moon ({@link MoonPosition}): its light above the air times the transmittance of the air towards it and the
 *     part of its disc above the horizon, as the sun's ({@link SkyLight}), from the direction of the moon.</li>
 * <li>The moonlit sky: the air scatters moonlight as it scatters sunlight, and a clear sky lit from 10° to 30° up
 *     gives level ground {@value #MOONLIT_SKY} of the light falling on a surface facing the light (the sky tables'
 *     ambient against their sun: 0.046 / 0.68 with the sun 20° up, 0.038 / 0.54 at 12°). It is added to the night
 *     sky as that much radiance, the same in every direction: the moonlit sky's glow around the moon and its blue are
 *     left out (at night the rods see no colour).</li>
 * </ul>
 *
 * @param moonDirection unit vector towards the moon, world space
 * @param moon          the moon's light at the eye on a surface facing it
 * @param sky           π × the night sky's radiance, the same in every direction above the horizon
 * @param moonDisc      π × the radiance of the lit part of the moon's disc: the moon's light over its lit area
 */
public record NightLight(Vector3fc moonDirection, Vector3d moon, Vector3d sky, Vector3d moonDisc) {

    /** π × the radiance of a moonless night sky, display units (class comment). */
    static final double SKY = 5.8e-9;
    /** The moonlit sky's light on level ground against the moon's on a surface facing it (class comment). */
    static final double MOONLIT_SKY = 0.07;

    /** The night's light at this clock and eye altitude (metres), for the sky settings {@code s}. */
    public static NightLight of(AtmosphereTables t, SkySettings s, double hours, double altitudeM) {
        Vector3f toMoon = MoonPosition.direction(hours, s.latitude(), s.declination(), s.moonAge());
        Vector3d moon = SkyLight.sunlight(t, Math.asin(toMoon.y), altitudeM).mul(MoonPosition.irradiance(s.moonAge()));
        double radius = Math.toRadians(MoonPosition.ANGULAR_RADIUS_DEG);
        double lit = Math.max(MoonPosition.litFraction(s.moonAge()), 1e-3); // a thousandth: no division by a new moon
        Vector3d sky = new Vector3d(moon).mul(MOONLIT_SKY).add(SKY, SKY, SKY);
        return new NightLight(toMoon, moon, sky, new Vector3d(moon).div(radius * radius * lit));
    }

    /** The night's light on level ground: the moon's by the sine of its elevation, and the sky's. */
    public Vector3d onLevelGround() {
        return new Vector3d(moon).mul(Math.max(moonDirection.y(), 0)).add(sky);
    }
}

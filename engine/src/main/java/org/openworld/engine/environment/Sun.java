package org.openworld.engine.environment;

import org.joml.Vector3f;
import org.joml.Vector3fc;
import org.openworld.engine.gl.SharedTexture;

/**
 * The sun as the world sees it: the unit direction towards it and the light it gives at the ground, linear RGB
 * (1 = the white of noon on a clear day). The ambient term is the light from the whole sky on a surface facing up;
 * the sky term the light of the sky and of the sunlit ground around on a surface of any normal.
 * Written by the system that models the sky; read by everything that is lit.
 *
 * @param direction unit vector from the ground towards the sun, world space
 * @param color     direct sunlight at the ground, linear RGB
 * @param ambient   sky light on an upward surface, linear RGB
 * @param sky       sky and ground light for any normal (spherical harmonics), linear RGB
 */
public record Sun(Vector3fc direction, Vector3fc color, Vector3fc ambient, SkyIrradiance sky) {

    /**
     * The sun's angular radius seen from the Earth, degrees: the sky fades it out as it sets, and its disc blurs the
     * edges of shadows (0.93 cm of soft edge per metre between the caster and the ground).
     */
    public static final double ANGULAR_RADIUS_DEG = 0.2666;

    /** The sun of a world with no system that models the sky: high (65°) towards the north-east, white. */
    public static final Sun NOON = new Sun(new Vector3f(0.3f, 0.9f, -0.3f), new Vector3f(1),
            new Vector3f(SharedTexture.NEUTRAL_SKY));

    /** A sun under a uniform sky of upward irradiance {@code ambient} over a black ground. */
    public Sun(Vector3fc direction, Vector3fc color, Vector3fc ambient) {
        this(direction, color, ambient, SkyIrradiance.uniformSky(ambient));
    }

    public Sun {
        direction = new Vector3f(direction).normalize();
        color = new Vector3f(color);
        ambient = new Vector3f(ambient);
    }

    /** Elevation above the horizon, degrees. */
    public double elevationDegrees() {
        return Math.toDegrees(Math.asin(direction.y()));
    }
}

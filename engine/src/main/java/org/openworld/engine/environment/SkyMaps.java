package org.openworld.engine.environment;

import org.openworld.engine.gl.CubeMapTexture;
import org.openworld.engine.gl.Texture3D;

/**
 * The sky's light as textures, for every lit shader: the engine binds them to their
 * {@link org.openworld.engine.gl.SharedTexture} units before each pass. Owned (created and closed) by the system that
 * models the sky; without one, the engine binds neutral stand-ins.
 *
 * @param aerialPerspective in-scattered light and transmittance per view direction and distance
 *                          ({@code shaders/common/fog.glsl})
 * @param environment       the sky's radiance around the scene, mip-mapped ({@code shaders/common/environment.glsl})
 */
public record SkyMaps(Texture3D aerialPerspective, CubeMapTexture environment) {
}

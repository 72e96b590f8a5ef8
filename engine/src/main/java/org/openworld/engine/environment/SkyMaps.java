package org.openworld.engine.environment;

import org.openworld.engine.core.SharedResource;
import org.openworld.engine.gl.CubeMapTexture;
import org.openworld.engine.gl.SharedTexture;
import org.openworld.engine.gl.Texture3D;

/**
 * The sky's light as textures, for every lit shader: shared with every pass ({@link SharedResource}), on their
 * {@link SharedTexture} units. Owned (created and closed) by the system that models the sky; without one, the engine
 * binds the stand-ins (clear air, a uniform sky as bright as {@link Sun#NOON}'s ambient light).
 *
 * @param aerialPerspective in-scattered light and transmittance per view direction and distance
 *                          ({@code shaders/common/fog.glsl})
 * @param environment       the sky's radiance around the scene, mip-mapped ({@code shaders/common/environment.glsl})
 */
public record SkyMaps(Texture3D aerialPerspective, CubeMapTexture environment) implements SharedResource {

    @Override
    public void bindShared() {
        aerialPerspective.bind(SharedTexture.AERIAL_PERSPECTIVE.unit());
        environment.bind(SharedTexture.ENVIRONMENT.unit());
    }
}

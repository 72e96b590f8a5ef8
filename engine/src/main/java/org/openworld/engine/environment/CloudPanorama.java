package org.openworld.engine.environment;

import org.openworld.engine.gl.Texture2D;

/**
 * The volumetric clouds in every direction from the viewer's eye, for what draws the sky without marching them: the
 * water's reflection and the sky's environment map. Laid out as the sky's panorama ({@code shaders/sky/panorama.glsl}:
 * the upper hemisphere's square on the left, the lower's on the right), renewed a band of rows per frame by the
 * volumetric clouds, which own it; absent without them (the sky then draws its layer).
 *
 * @param texture 2N × N, RGBA16F, linear: rgb the clouds' light towards the eye after the air in front of them
 *                (display units), a the transmittance ({@code shaders/clouds/panorama.frag})
 */
public record CloudPanorama(Texture2D texture) {
}

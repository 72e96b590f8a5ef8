package org.openworld.engine.gl;

/**
 * Textures every shader may sample without its system binding them: the engine binds each to its fixed unit before
 * every pass, and every program that declares the sampler gets it set to that unit at link time. Units count down
 * from the top of the 16 a fragment shader is guaranteed, so systems' own units (from 0) never meet them.
 */
public enum SharedTexture {
    /** {@code sampler2D cloudShadowMap}: the sunlight the clouds let through ({@code shaders/common/shadow.glsl}). */
    CLOUD_SHADOW_MAP("cloudShadowMap", 12),
    /** {@code sampler2DArrayShadow shadowMap}: the sun's shadow cascades ({@code shaders/common/shadow.glsl}). */
    SHADOW_MAP("shadowMap", 13),
    /** {@code samplerCube environmentMap}: the sky around the scene ({@code shaders/common/environment.glsl}). */
    ENVIRONMENT("environmentMap", 14),
    /** {@code sampler3D aerialPerspective}: the air's in-scattering and transmittance ({@code common/fog.glsl}). */
    AERIAL_PERSPECTIVE("aerialPerspective", 15);

    private final String sampler;
    private final int unit;

    SharedTexture(String sampler, int unit) {
        this.sampler = sampler;
        this.unit = unit;
    }

    /** The sampler's name in GLSL. */
    public String sampler() {
        return sampler;
    }

    /** The texture unit it is bound to. */
    public int unit() {
        return unit;
    }
}

package org.openworld.engine.gl;

/**
 * Textures every shader may sample without its system binding them: the engine binds each to its fixed unit before
 * every pass, and every program that declares the sampler gets it set to that unit at link time. They take the top
 * units of the 16 a fragment shader is guaranteed, in the order declared here, so systems' own units
 * ({@link TextureUnits}, from 0) never meet them.
 */
public enum SharedTexture {
    /** {@code sampler2DArrayShadow shadowMap}: the sun's shadow cascades ({@code shaders/common/shadow.glsl}). */
    SHADOW_MAP("shadowMap"),
    /** {@code samplerCube environmentMap}: the sky around the scene ({@code shaders/common/environment.glsl}). */
    ENVIRONMENT("environmentMap"),
    /** {@code sampler3D aerialPerspective}: the air's in-scattering and transmittance ({@code common/fog.glsl}). */
    AERIAL_PERSPECTIVE("aerialPerspective");

    /** Texture units a fragment shader is guaranteed (GL_MAX_TEXTURE_IMAGE_UNITS is at least 16 in OpenGL 3.3). */
    private static final int GUARANTEED_UNITS = 16;

    private final String sampler;

    SharedTexture(String sampler) {
        this.sampler = sampler;
    }

    /** The first unit the shared textures take: the units below it are the systems' own. */
    static int lowestUnit() {
        return GUARANTEED_UNITS - values().length;
    }

    /** The sampler's name in GLSL. */
    public String sampler() {
        return sampler;
    }

    /** The texture unit it is bound to. */
    public int unit() {
        return lowestUnit() + ordinal();
    }
}

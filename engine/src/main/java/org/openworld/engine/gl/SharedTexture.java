package org.openworld.engine.gl;

import java.nio.FloatBuffer;
import org.joml.Vector3f;
import org.lwjgl.system.MemoryUtil;

/**
 * Textures every shader may sample without its system binding them: the engine binds each to its fixed unit before
 * every pass, and every program that declares the sampler gets it set to that unit at link time. They take the top
 * units of the 16 a fragment shader is guaranteed, in the order declared here, so systems' own units
 * ({@link TextureUnits}, from 0) never meet them.
 */
public enum SharedTexture {
    /** {@code sampler2D cloudShadowMap}: the sunlight the clouds let through ({@code shaders/common/shadow.glsl}). */
    CLOUD_SHADOW_MAP("cloudShadowMap"),
    /** {@code sampler2DArrayShadow shadowMap}: the sun's shadow cascades ({@code shaders/common/shadow.glsl}). */
    SHADOW_MAP("shadowMap"),
    /** {@code samplerCube environmentMap}: the sky around the scene ({@code shaders/common/environment.glsl}). */
    ENVIRONMENT("environmentMap"),
    /** {@code sampler3D aerialPerspective}: the air's in-scattering and transmittance ({@code common/fog.glsl}). */
    AERIAL_PERSPECTIVE("aerialPerspective"),
    /** {@code sampler2D forestCoverMap}: the forests beyond the plants' reach ({@code shaders/common/forest.glsl}). */
    FOREST_COVER("forestCoverMap");

    /**
     * The radiance of the stand-in {@link #ENVIRONMENT}, a uniform sky, linear RGB (1 = the white of noon on a clear
     * day): the ambient light of the sun a world without a sky has ({@code Sun.NOON}), so the two light alike.
     */
    public static final float NEUTRAL_SKY = 0.3f;

    /** Texture units a fragment shader is guaranteed (GL_MAX_TEXTURE_IMAGE_UNITS is at least 16 in OpenGL 3.3). */
    private static final int GUARANTEED_UNITS = 16;

    private final String sampler;

    SharedTexture(String sampler) {
        this.sampler = sampler;
    }

    /**
     * A texture of one texel that stands in for this one where no shared resource binds it, and changes nothing:
     * a cloud shadow of transmittance 1, a shadow map at the far plane (everything lit), a uniform sky of {@link #NEUTRAL_SKY}, clear air (nothing
     * scattered in, everything transmitted), no forest (its block's strength 0 is never past; the texel is unread).
     */
    public GlTexture standIn(GlContext gl) {
        return switch (this) {
            case CLOUD_SHADOW_MAP -> sunThrough(gl);
            case SHADOW_MAP -> DepthTextureArray.empty(gl);
            case ENVIRONMENT -> CubeMapTexture.fromDirections(gl, 1, d -> new Vector3f(NEUTRAL_SKY));
            case AERIAL_PERSPECTIVE -> clearAir(gl);
            case FOREST_COVER -> Texture2D.empty(gl, 1, 1, Format.RGBA8, Sampling.NEAREST_CLAMP);
        };
    }

    /** One texel of transmittance 1: every ray of sunlight through. */
    private static Texture2D sunThrough(GlContext gl) {
        FloatBuffer through = MemoryUtil.memAllocFloat(1).put(1).flip();
        try {
            Texture2D map = Texture2D.empty(gl, 1, 1, Format.R16F, Sampling.NEAREST_CLAMP);
            map.upload(0, 0, 1, through);
            return map;
        } finally {
            MemoryUtil.memFree(through);
        }
    }

    private static Texture3D clearAir(GlContext gl) {
        FloatBuffer transmitted = MemoryUtil.memAllocFloat(4).put(0).put(0).put(0).put(1).flip();
        try {
            return Texture3D.of(gl, 1, 1, 1, Format.RGBA16F, Sampling.LINEAR_CLAMP, transmitted);
        } finally {
            MemoryUtil.memFree(transmitted);
        }
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

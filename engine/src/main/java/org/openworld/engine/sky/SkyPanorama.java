package org.openworld.engine.sky;

import static org.lwjgl.opengl.GL30C.*;

import org.joml.Vector4fc;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Texture2D;
import org.openworld.engine.gl.TextureUnits;
import org.openworld.engine.gl.Uniform;

/**
 * The sky and its clouds in every direction, drawn into textures ({@code shaders/sky/panorama.frag}, layout in
 * {@code sky/panorama.glsl}): two hemi-octahedral squares side by side, the upper hemisphere and the lower, each
 * with the zenith (nadir) at its centre and the horizon its border. Two textures, drawn at once: the sky behind the
 * clouds with the cloud's density above its threshold, and the cloud's colour with what the horizon fog leaves of
 * it. The sky pass draws the cloud's edge per pixel from the interpolated density ({@code cloudOpacity}), as a
 * smoothstep of the bilinear density is round where a bilinear opacity would show the texel grid, and adds the sun's
 * disc per pixel, so its edge stays sharp.
 *
 * <p>The sky pass and the environment map read it with one lookup per texture instead of evaluating the dome, the
 * distant ground and the cloud layer for every pixel of every frame; it is redrawn only when the sun or the clouds
 * moved ({@link SkySystem#PANORAMA_REFRESH}). {@link #SIZE} was chosen by looking: at 576² a hemisphere a texel is
 * 0.16° along the horizon and 0.31° from the horizon towards the zenith (within a factor of 2 everywhere), several
 * texels to one of the 128² cloud field's wherever the horizon fog leaves a cloud to see.
 */
final class SkyPanorama {

    /** Texels along a side of each hemisphere's square; the textures are 2 SIZE × SIZE. */
    static final int SIZE = 576;
    private static final TextureUnits DRAWN_FROM = new TextureUnits();
    /** The tables the panorama is drawn from. */
    static final TextureUnits.Sampler VIEW = DRAWN_FROM.add("skyView");
    static final TextureUnits.Sampler CLOUDS = DRAWN_FROM.add("cloudField");
    static final TextureUnits.Sampler AIR = DRAWN_FROM.add("airTable");
    private static final TextureUnits DRAWN_WITH = new TextureUnits();
    /** The panorama itself, sky and clouds, where the sky and the stars are drawn from it. */
    static final TextureUnits.Sampler SKY_PANORAMA = DRAWN_WITH.add("skyPanorama");
    static final TextureUnits.Sampler CLOUD_PANORAMA = DRAWN_WITH.add("cloudPanorama");
    /** The volumetric clouds' panorama ({@link org.openworld.engine.environment.CloudPanorama}), where there is one. */
    static final TextureUnits.Sampler CLOUD_VOLUME = DRAWN_WITH.add("cloudVolume");

    private final ShaderProgram program;
    private final Texture2D sky;
    private final Texture2D clouds;
    private final Framebuffer target;
    private final Uniform.Vec2 size;
    private final Uniform.Vec3 sunDir;
    private final Uniform.Vec3 sunColor;
    private final Uniform.Vec3 ambientColor;
    private final Uniform.Float altitude;
    private final Uniform.Float groundAlbedo;
    private final Uniform.Float radianceScale;
    private final Uniform.Vec4 cloudParams;
    private final Uniform.Vec4 cloudMotion;

    SkyPanorama(EngineContext context) {
        program = context.own("panoramaProgram", context.shaders().program("sky/sky.vert", "sky/panorama.frag"));
        program.sampler(VIEW);
        program.sampler(CLOUDS);
        program.sampler(AIR);
        size = program.vec2("uSize");
        sunDir = program.vec3("uSunDir");
        sunColor = program.vec3("uSunColor");
        ambientColor = program.vec3("uAmbientColor");
        altitude = program.float1("uAltitude");
        groundAlbedo = program.float1("uGroundAlbedo");
        radianceScale = program.float1("uScale");
        cloudParams = program.vec4("cloudParams");
        cloudMotion = program.vec4("cloudMotion");
        sky = context.own("panorama.sky", Texture2D.empty(context.gl(), 2 * SIZE, SIZE, Format.RGBA16F,
                Sampling.LINEAR_CLAMP));
        clouds = context.own("panorama.clouds", Texture2D.empty(context.gl(), 2 * SIZE, SIZE, Format.RGBA16F,
                Sampling.LINEAR_CLAMP));
        target = context.own("panorama", Framebuffer.onTextures(context.gl(), sky, clouds));
    }

    /**
     * Draws the panorama for a sun and its light, the eye's altitude and the clouds of the moment, with the tables
     * already bound to {@link #VIEW}, {@link #CLOUDS} and {@link #AIR}; leaves the framebuffer and the
     * viewport as they were. The colours are stored times {@code scale} (after sunset 1 / the light on the ground,
     * display units): the night's radiance, 10⁻⁹ of the sun's, lies far below a half float's normal range (6·10⁻⁵), where it keeps a
     * few bits or none, and relative to the ground's light every hour's sky is within it. Readers divide
     * ({@code sky/night.glsl}).
     */
    void draw(Sun sun, double altitudeM, double albedo, float scale, Vector4fc clouds, Vector4fc motion,
              Mesh fullScreen, DrawStats stats) {
        int previous = glGetInteger(GL_DRAW_FRAMEBUFFER_BINDING);
        int[] viewport = new int[4];
        glGetIntegerv(GL_VIEWPORT, viewport);
        program.use();
        size.set(2 * SIZE, SIZE);
        sunDir.set(sun.direction());
        sunColor.set(sun.color());
        ambientColor.set(sun.ambient());
        altitude.set((float) altitudeM);
        groundAlbedo.set((float) albedo);
        radianceScale.set(scale);
        cloudParams.set(clouds);
        cloudMotion.set(motion);
        target.bind(); // no depth buffer: the depth test passes whatever its state
        fullScreen.draw(stats);
        glBindFramebuffer(GL_FRAMEBUFFER, previous);
        glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    }

    /** The sky behind the clouds (rgb) and the cloud's density above the threshold (alpha). */
    Texture2D sky() {
        return sky;
    }

    /** The clouds' colour (rgb) and what the horizon fog leaves of them (alpha). */
    Texture2D clouds() {
        return clouds;
    }
}

package org.openworld.engine.sky;

import static org.lwjgl.opengl.GL11C.GL_FLOAT;
import static org.lwjgl.opengl.GL11C.GL_POINTS;
import static org.lwjgl.opengl.GL11C.glDrawArrays;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_STATIC_DRAW;
import static org.lwjgl.opengl.GL20C.glEnableVertexAttribArray;
import static org.lwjgl.opengl.GL20C.glVertexAttribPointer;
import static org.lwjgl.opengl.GL30C.glBindVertexArray;

import java.nio.FloatBuffer;
import org.joml.Matrix3fc;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.GpuBuffer;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Uniform;
import org.openworld.engine.gl.VertexArray;

/**
 * The stars of a {@link StarCatalogue}, drawn over the sky pass: each one pixel (a point of the default size, one
 * vertex per star, all in one draw), on the far plane and depth-tested as the sky is, so the terrain hides them.
 * Its fragment shader ({@code sky/stars.frag}) draws the sky of that pixel again with the star on it: the star's light
 * over the pixel's solid angle, π·E / Ω, behind the clouds.
 *
 * <p>Skipped while the brightest star would show below {@link #VISIBLE} of white: by day, and in the twilight until
 * the sky darkens. Points rather than instanced squares of a pixel: on llvmpipe the vertex work is the cost (the
 * rasteriser runs the vertex shader on the drawing thread), and a point is one vertex where a square is four.
 */
final class StarField {

    /** Exposed light of the brightest star below which no star is drawn: about a quarter of an 8-bit level. */
    static final double VISIBLE = 1e-3;
    /** The vertex attribute: a star's direction and light. */
    private static final int STAR = 0;

    private final ShaderProgram program;
    private final Uniform.Mat3 toWorld;
    private final NightUniforms night;
    private final VertexArray points;
    private final int count;
    private final double brightest;

    StarField(EngineContext context, StarCatalogue catalogue) {
        program = context.own("starsProgram", context.shaders().program("sky/stars.vert", "sky/stars.frag"));
        program.sampler(SkyPanorama.SKY_PANORAMA);
        program.sampler(SkyPanorama.CLOUD_PANORAMA);
        toWorld = program.mat3("uEquatorialToWorld");
        night = new NightUniforms(program);
        count = catalogue.count();
        brightest = catalogue.irradiance()[0];
        points = context.own("starPoints", new VertexArray(context.gl()));
        GpuBuffer stars = context.own("stars", new GpuBuffer(context.gl(), GL_ARRAY_BUFFER));
        FloatBuffer data = MemoryUtil.memAllocFloat(4 * count);
        try {
            for (int i = 0; i < count; i++) {
                data.put(catalogue.directions(), 3 * i, 3).put(catalogue.irradiance()[i]);
            }
            stars.upload(data.flip(), GL_STATIC_DRAW);
        } finally {
            MemoryUtil.memFree(data);
        }
        points.bind();
        stars.bind();
        glEnableVertexAttribArray(STAR);
        glVertexAttribPointer(STAR, 4, GL_FLOAT, false, 4 * Float.BYTES, 0);
        glBindVertexArray(0);
    }

    /**
     * Whether a star would show at the exposure {@code exposure} on a picture whose pixels span {@code pixelSolidAngle}
     * steradians: the brightest star's exposed light π·E / Ω against {@link #VISIBLE}.
     */
    boolean visible(double exposure, double pixelSolidAngle) {
        return Math.PI * brightest / pixelSolidAngle * exposure >= VISIBLE;
    }

    /** Draws the stars turned by {@code equatorialToWorld}; the sky pass's depth state and panorama are bound. */
    void draw(Matrix3fc equatorialToWorld, NightLight light, float panoramaScale, DrawStats stats) {
        program.use();
        toWorld.set(equatorialToWorld);
        night.set(light, panoramaScale);
        points.bind();
        glDrawArrays(GL_POINTS, 0, count);
        glBindVertexArray(0);
        stats.add(1, 0);
    }

    /** The uniforms of {@code sky/night.glsl}, in the sky's program and the stars'. */
    static final class NightUniforms {
        private final Uniform.Float scale;
        private final Uniform.Vec3 sky;
        private final Uniform.Vec3 moonDir;
        private final Uniform.Vec3 moonDisc;

        NightUniforms(ShaderProgram program) {
            scale = program.float1("uPanoramaScale");
            sky = program.vec3("uNightSky");
            moonDir = program.vec3("uMoonDir");
            moonDisc = program.vec3("uMoonDisc");
        }

        /** Sets them in the program in use, with the scale the panorama was drawn at (SkyPanorama#draw). */
        void set(NightLight light, float panoramaScale) {
            scale.set(panoramaScale);
            sky.set((float) light.sky().x, (float) light.sky().y, (float) light.sky().z);
            moonDir.set(light.moonDirection());
            moonDisc.set((float) light.moonDisc().x, (float) light.moonDisc().y, (float) light.moonDisc().z);
        }
    }
}

package org.openworld.engine.sky;

import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_STATIC_DRAW;

import java.nio.FloatBuffer;
import org.joml.Matrix3fc;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.GpuBuffer;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Uniform;

/**
 * The stars of a {@link StarCatalogue}, drawn over the sky pass: each one pixel (a square of one pixel's side, one
 * instance per star, all in one draw), on the far plane and depth-tested as the sky is, so the terrain hides them.
 * Its fragment shader ({@code sky/stars.frag}) draws the sky of that pixel again with the star on it: the star's light
 * over the pixel's solid angle, π·E / Ω, behind the clouds.
 *
 * <p>Skipped while the brightest star would show below {@link #VISIBLE} of white: by day, and in the twilight until
 * the sky darkens. Cost at night: 4600 squares of one pixel, well under a millisecond on llvmpipe.
 */
final class StarField {

    /** Exposed light of the brightest star below which no star is drawn: about a quarter of an 8-bit level. */
    static final double VISIBLE = 1e-3;
    /** The vertex attributes: a corner of the square, and per star its direction and light. */
    private static final int CORNER = 0;
    private static final int STAR = 1;

    private final ShaderProgram program;
    private final Uniform.Mat3 toWorld;
    private final NightUniforms night;
    private final Mesh square;
    private final int count;
    private final double brightest;

    StarField(EngineContext context, StarCatalogue catalogue) {
        program = context.own("starsProgram", context.shaders().program("sky/stars.vert", "sky/stars.frag"));
        program.sampler("skyPanorama", 0);
        program.sampler("cloudPanorama", 1);
        toWorld = program.mat3("uEquatorialToWorld");
        night = new NightUniforms(program);
        square = context.own("starSquare", new Mesh(context.gl(), new float[] {-0.5f, -0.5f, 0.5f, -0.5f, 0.5f, 0.5f,
                -0.5f, 0.5f}, new int[] {0, 1, 2, 0, 2, 3}, new Mesh.Attribute(CORNER, 2)));
        count = catalogue.count();
        brightest = catalogue.irradiance()[0];
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
        square.instances(stars, 4, new Mesh.Attribute(STAR, 4));
    }

    /**
     * Whether a star would show at the exposure {@code exposure} on a picture whose pixels span {@code pixelSolidAngle}
     * steradians: the brightest star's exposed light π·E / Ω against {@link #VISIBLE}.
     */
    boolean visible(double exposure, double pixelSolidAngle) {
        return Math.PI * brightest / pixelSolidAngle * exposure >= VISIBLE;
    }

    /** Draws the stars turned by {@code equatorialToWorld}; the sky pass's depth state and panorama are bound. */
    void draw(Matrix3fc equatorialToWorld, NightLight light, DrawStats stats) {
        program.use();
        toWorld.set(equatorialToWorld);
        night.set(light);
        square.drawInstances(0, count, stats);
    }

    /** The night's uniforms of {@code sky/night.glsl}, in the sky's program and the stars'. */
    static final class NightUniforms {
        private final Uniform.Vec3 sky;
        private final Uniform.Vec3 moonDir;
        private final Uniform.Vec3 moonDisc;

        NightUniforms(ShaderProgram program) {
            sky = program.vec3("uNightSky");
            moonDir = program.vec3("uMoonDir");
            moonDisc = program.vec3("uMoonDisc");
        }

        /** Sets them in the program in use. */
        void set(NightLight light) {
            sky.set((float) light.sky().x, (float) light.sky().y, (float) light.sky().z);
            moonDir.set(light.moonDirection());
            moonDisc.set((float) light.moonDisc().x, (float) light.moonDisc().y, (float) light.moonDisc().z);
        }
    }
}

package org.openworld.engine.water;

import java.util.List;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.TextureUnits;
import org.openworld.engine.gl.Uniform;
import org.openworld.engine.origin.RenderOrigin;

/**
 * The water's three programs over one vertex shader (water.vert) and their uniforms: the Fresnel method above the
 * water (fresnel.frag) and under it (underwater.frag), two programs rather than one with a branch, since a software
 * rasteriser runs both sides of a branch; and the paper's stencil method (stencil.frag). The two Fresnel programs
 * come twice, with the sun's shadow lookup and compiled without it ({@code SUN_UNSHADOWED}) for passes where no shadow
 * map is bound: a software rasteriser runs the lookup's loop once even for no cascade (docs/shadows.md). Each
 * {@code use} binds one and sets its uniforms; the caller binds the textures to the samplers' units below and draws.
 */
final class WaterPrograms {

    private static final TextureUnits UNITS = new TextureUnits();
    static final TextureUnits.Sampler REFLECTION = UNITS.add("reflection");
    static final TextureUnits.Sampler REFRACTION = UNITS.add("refraction");
    static final TextureUnits.Sampler DEPTH = UNITS.add("depthCopy");
    static final TextureUnits.Sampler FRESNEL = UNITS.add("fresnelTable");
    static final TextureUnits.Sampler RIPPLES = UNITS.add("ripples");

    /**
     * What the Fresnel programs are told of the ripples, see water/optics.glsl's uRipple and uRippleOrigin (the render
     * origin's place on the two layers' tiles, {@link #originTiles}).
     */
    record Ripple(float inverseTile, int frames, float cycles, float slopeScale, float[] origin) {

        /** optics.glsl's SMALL_SCALE: the second layer's tile, a share of the first's. */
        static final double SMALL_SCALE = 0.37;

        /**
         * The render origin (x, 0, z) in tiles of the two layers, reduced to [0, 1) in double: the tiles repeat, so
         * this is all of it that the shader needs.
         */
        static float[] originTiles(double x, double z, double tile) {
            double small = tile * SMALL_SCALE;
            return new float[] {(float) (RenderOrigin.reduce(x, tile) / tile),
                (float) (RenderOrigin.reduce(z, tile) / tile), (float) (RenderOrigin.reduce(x, small) / small),
                (float) (RenderOrigin.reduce(z, small) / small)};
        }
    }

    private final Above above;
    private final Above aboveUnshadowed;
    private final Below below;
    private final Below belowUnshadowed;
    private final ShaderProgram stencil;
    private final Plane stencilPlane;
    private final Uniform.Int stencilStep;
    private final Uniform.Float stencilAlpha;

    /** Where the plane lies on the screen (water.vert): its NDC depth and the horizon that cuts it. */
    private record Plane(Uniform.Vec3 depth, Uniform.Vec3 horizon) {

        static Plane of(ShaderProgram program) {
            return new Plane(program.vec3("uDepthPlane"), program.vec3("uHorizon"));
        }

        /** The plane's depth and horizon; null for a full-screen triangle at depth 0, uncut. */
        void set(PlaneOnScreen plane) {
            if (plane == null) {
                depth.set(0, 0, 0);
                horizon.set(0, 0, 1);
            } else {
                depth.set(plane.depth());
                horizon.set(plane.horizon());
            }
        }
    }

    /** The uniforms of water/optics.glsl, which both Fresnel programs include. */
    private record Optics(Plane plane, Uniform.Float level, Uniform.Vec3 extinction, Uniform.Vec4 ripple,
                          Uniform.Vec4 rippleOrigin) {

        static Optics of(ShaderProgram program) {
            program.sampler(REFRACTION);
            program.sampler(DEPTH);
            program.sampler(FRESNEL);
            program.sampler(RIPPLES);
            return new Optics(Plane.of(program), program.float1("uLevel"), program.vec3("uExtinction"),
                    program.vec4("uRipple"), program.vec4("uRippleOrigin"));
        }

        void set(PlaneOnScreen plane, float waterLevel, WaterOptics optics, Ripple r) {
            this.plane.set(plane);
            level.set(waterLevel);
            extinction.set(optics.extinction());
            ripple.set(r.inverseTile(), r.frames(), r.cycles(), r.slopeScale());
            rippleOrigin.set(r.origin()[0], r.origin()[1], r.origin()[2], r.origin()[3]);
        }
    }

    /** The water seen from above (fresnel.frag) and its uniforms, for one kind of sunlight. */
    private record Above(ShaderProgram program, Optics optics, Uniform.Int reflected, Uniform.Vec3 body,
                         Uniform.Float microSlope2, Uniform.Float resolvedSlope2) {

        static Above of(EngineContext context, String role, List<String> light) {
            ShaderProgram p = context.own(role, context.shaders().program(light, "water/water.vert",
                    "water/fresnel.frag"));
            p.sampler(REFLECTION);
            return new Above(p, Optics.of(p), p.int1("uReflected"), p.vec3("uBody"), p.float1("uMicroSlope2"),
                    p.float1("uResolvedSlope2"));
        }
    }

    /** The water seen from below (underwater.frag) and its uniforms, for one kind of sunlight. */
    private record Below(ShaderProgram program, Optics optics, Uniform.Vec3 inside) {

        static Below of(EngineContext context, String role, List<String> light) {
            ShaderProgram p = context.own(role, context.shaders().program(light, "water/water.vert",
                    "water/underwater.frag"));
            return new Below(p, Optics.of(p), p.vec3("uInside"));
        }
    }

    WaterPrograms(EngineContext context) {
        above = Above.of(context, "fresnel", List.of());
        aboveUnshadowed = Above.of(context, "fresnel.unshadowed", List.of("SUN_UNSHADOWED"));
        below = Below.of(context, "underwater", List.of());
        belowUnshadowed = Below.of(context, "underwater.unshadowed", List.of("SUN_UNSHADOWED"));
        stencil = context.own("stencil", context.shaders().program("water/water.vert", "water/stencil.frag"));
        stencil.sampler(REFLECTION);
        stencilPlane = Plane.of(stencil);
        stencilStep = stencil.int1("uStep");
        stencilAlpha = stencil.float1("uAlpha");
    }

    /**
     * The water seen from above, drawn as the plane on the screen.
     *
     * @param hasReflection whether the reflection pass ran for this camera this frame
     * @param glitterSlope2 mean square slope of the ripples finer than the texture
     * @param resolvedSlope2 mean square slope of the ripples the texture holds: where a pixel is too coarse to show
     *                       them, the shader moves this variance from the normal into the glitter's lobe
     * @param sunShadowed   the pass has the sun's shadow maps bound (RenderContext#shares)
     */
    void useAbove(PlaneOnScreen plane, float level, WaterOptics optics, Ripple ripple, boolean hasReflection,
                  float glitterSlope2, float resolvedSlope2, boolean sunShadowed) {
        Above a = sunShadowed ? above : aboveUnshadowed;
        a.program().use();
        a.optics().set(plane, level, optics, ripple);
        a.reflected().set(hasReflection ? 1 : 0);
        a.body().set(optics.body());
        a.microSlope2().set(glitterSlope2);
        a.resolvedSlope2().set(resolvedSlope2);
    }

    /** The water seen from below, a full-screen triangle that writes its own depth. */
    void useBelow(float level, WaterOptics optics, Ripple ripple, boolean sunShadowed) {
        Below b = sunShadowed ? below : belowUnshadowed;
        b.program().use();
        b.optics().set(null, level, optics, ripple);
        b.inside().set(optics.inside());
    }

    /**
     * The paper's method: step 2 (the plane on the screen, alpha only) or step 4 (the reflection, full screen).
     *
     * @param plane the plane for step 2, null for step 4's full-screen triangle
     */
    void useStencil(int step, float alpha, PlaneOnScreen plane) {
        stencil.use();
        stencilStep.set(step);
        stencilAlpha.set(alpha);
        stencilPlane.set(plane);
    }
}

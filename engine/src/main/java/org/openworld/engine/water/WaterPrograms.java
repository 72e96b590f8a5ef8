package org.openworld.engine.water;

import org.openworld.engine.core.EngineContext;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Uniform;

/**
 * The water's three programs over one vertex shader (water.vert) and their uniforms: the Fresnel method above the
 * water (fresnel.frag) and under it (underwater.frag), two programs rather than one with a branch, since a software
 * rasteriser runs both sides of a branch; and the paper's stencil method (stencil.frag). Each {@code use} binds one
 * and sets its uniforms; the caller binds the textures to the units below and draws.
 */
final class WaterPrograms {

    static final int UNIT_REFLECTION = 0;
    static final int UNIT_REFRACTION = 1;
    static final int UNIT_DEPTH = 2;
    static final int UNIT_FRESNEL = 3;
    static final int UNIT_RIPPLES = 4;

    /** What the Fresnel programs are told of the ripples, see water/optics.glsl's uRipple. */
    record Ripple(float inverseTile, int frames, float cycles, float slopeScale) {
    }

    private final ShaderProgram above;
    private final ShaderProgram below;
    private final ShaderProgram stencil;
    private final Optics aboveOptics;
    private final Optics belowOptics;
    private final Uniform.Int reflected;
    private final Uniform.Vec3 body;
    private final Uniform.Float microSlope2;
    private final Uniform.Vec3 inside;
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
    private record Optics(Plane plane, Uniform.Float level, Uniform.Vec3 extinction, Uniform.Vec4 ripple) {

        static Optics of(ShaderProgram program) {
            program.sampler("refraction", UNIT_REFRACTION);
            program.sampler("depthCopy", UNIT_DEPTH);
            program.sampler("fresnelTable", UNIT_FRESNEL);
            program.sampler("ripples", UNIT_RIPPLES);
            return new Optics(Plane.of(program), program.float1("uLevel"), program.vec3("uExtinction"),
                    program.vec4("uRipple"));
        }

        void set(PlaneOnScreen plane, float waterLevel, WaterOptics optics, Ripple r) {
            this.plane.set(plane);
            level.set(waterLevel);
            extinction.set(optics.extinction());
            ripple.set(r.inverseTile(), r.frames(), r.cycles(), r.slopeScale());
        }
    }

    WaterPrograms(EngineContext context) {
        above = context.own("fresnel", context.shaders().program("water/water.vert", "water/fresnel.frag"));
        above.sampler("reflection", UNIT_REFLECTION);
        aboveOptics = Optics.of(above);
        reflected = above.int1("uReflected");
        body = above.vec3("uBody");
        microSlope2 = above.float1("uMicroSlope2");
        below = context.own("underwater", context.shaders().program("water/water.vert", "water/underwater.frag"));
        belowOptics = Optics.of(below);
        inside = below.vec3("uInside");
        stencil = context.own("stencil", context.shaders().program("water/water.vert", "water/stencil.frag"));
        stencil.sampler("reflection", UNIT_REFLECTION);
        stencilPlane = Plane.of(stencil);
        stencilStep = stencil.int1("uStep");
        stencilAlpha = stencil.float1("uAlpha");
    }

    /**
     * The water seen from above, drawn as the plane on the screen.
     *
     * @param hasReflection whether the reflection pass ran for this camera this frame
     * @param glitterSlope2 mean square slope of the ripples finer than the texture
     */
    void useAbove(PlaneOnScreen plane, float level, WaterOptics optics, Ripple ripple, boolean hasReflection,
                  float glitterSlope2) {
        above.use();
        aboveOptics.set(plane, level, optics, ripple);
        reflected.set(hasReflection ? 1 : 0);
        body.set(optics.body());
        microSlope2.set(glitterSlope2);
    }

    /** The water seen from below, a full-screen triangle that writes its own depth. */
    void useBelow(float level, WaterOptics optics, Ripple ripple) {
        below.use();
        belowOptics.set(null, level, optics, ripple);
        inside.set(optics.inside());
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

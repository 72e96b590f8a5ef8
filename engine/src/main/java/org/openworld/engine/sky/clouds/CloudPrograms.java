package org.openworld.engine.sky.clouds;

import org.joml.Matrix4fc;
import org.joml.Vector3fc;
import org.joml.Vector4fc;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.TextureUnits;
import org.openworld.engine.gl.Uniform;

/**
 * The clouds' five shader programs ({@code shaders/clouds/}) with their uniforms and texture units: the field's bake,
 * the shadow map, the march, the resolve and the composite, each a full-screen triangle
 * ({@code clouds/fullscreen.vert}).
 */
final class CloudPrograms {

    /** The samplers and their texture units: the field and the optics table (shadow, march), then each pass's own. */
    private static final TextureUnits UNITS = new TextureUnits();
    static final TextureUnits.Sampler FIELD = UNITS.add("cloudField");
    /** The base shape's 3D field, read by the bake only: the others read its 2D picture at this moment, FIELD. */
    static final TextureUnits.Sampler FIELD_VOLUME = UNITS.add("cloudFieldVolume");
    static final TextureUnits.Sampler OPTICS = UNITS.add("cloudOptics");
    static final TextureUnits.Sampler SCENE_DEPTH = UNITS.add("sceneDepth");
    static final TextureUnits.Sampler FRESH_LIGHT = UNITS.add("freshLight");
    static final TextureUnits.Sampler FRESH_DEPTH = UNITS.add("freshDepth");
    static final TextureUnits.Sampler HISTORY = UNITS.add("historyLight");
    static final TextureUnits.Sampler DETAIL = UNITS.add("cloudDetail");
    static final TextureUnits.Sampler LIGHT = UNITS.add("cloudLight");
    static final TextureUnits.Sampler DEPTH = UNITS.add("cloudDepth");
    /** The panorama's clouds, read by the water's reflection ({@link CloudPanoramaMarch}). */
    static final TextureUnits.Sampler PANORAMA = UNITS.add("cloudPanorama");

    final ShaderProgram bake;
    final ShaderProgram shadow;
    final ShaderProgram march;
    final ShaderProgram resolve;
    final ShaderProgram composite;
    private final Uniform.Vec2 bakeSize;
    private final Uniform.Float bakeTime;
    private final Uniform.Vec4 shadowLayer;
    private final Uniform.Vec4 shadowMotion;
    private final Uniform.Vec2 shadowSize;
    private final Uniform.Vec3 shadowEye;
    private final Uniform.Vec3 shadowSun;
    private final Uniform.Vec4 marchLayer;
    private final Uniform.Vec4 marchMotion;
    private final Uniform.Vec4 marchGrid;
    private final Uniform.Float marchEvery;
    private final Uniform.Mat4 resolvePrevious;
    private final Uniform.Vec4 resolveGrid;
    private final Uniform.Float resolveEvery;
    private final Uniform.Vec2 compositeGrid;
    private final Uniform.Float compositeSky;

    CloudPrograms(EngineContext context) {
        bake = program(context, "bakeProgram", "clouds/bake.frag");
        bake.sampler(FIELD_VOLUME);
        bakeSize = bake.vec2("uSize");
        bakeTime = bake.float1("uTime");

        shadow = program(context, "shadowProgram", "clouds/shadow.frag");
        shadow.sampler(FIELD);
        shadow.sampler(OPTICS);
        shadowLayer = shadow.vec4("uLayer");
        shadowMotion = shadow.vec4("uMotion");
        shadowSize = shadow.vec2("uSize");
        shadowEye = shadow.vec3("uEye");
        shadowSun = shadow.vec3("uSunDir");

        march = program(context, "marchProgram", "clouds/march.frag");
        march.sampler(FIELD);
        march.sampler(OPTICS);
        march.sampler(DETAIL);
        march.sampler(SCENE_DEPTH);
        marchLayer = march.vec4("uLayer");
        marchMotion = march.vec4("uMotion");
        marchGrid = march.vec4("uGrid");
        marchEvery = march.float1("uEveryTexel");

        resolve = program(context, "resolveProgram", "clouds/resolve.frag");
        resolve.sampler(SCENE_DEPTH);
        resolve.sampler(FRESH_LIGHT);
        resolve.sampler(FRESH_DEPTH);
        resolve.sampler(HISTORY);
        resolvePrevious = resolve.mat4("uPreviousViewProjection");
        resolveGrid = resolve.vec4("uGrid");
        resolveEvery = resolve.float1("uEveryTexel");

        composite = program(context, "compositeProgram", "clouds/composite.frag");
        composite.sampler(LIGHT);
        composite.sampler(DEPTH);
        compositeGrid = composite.vec2("uGridSize");
        compositeSky = composite.float1("uSky");
    }

    private static ShaderProgram program(EngineContext context, String role, String fragment) {
        return context.own(role, context.shaders().program("clouds/fullscreen.vert", fragment));
    }

    /** The bake's program in use, for a field of {@code size}² texels a tile at the time coordinate {@code time}. */
    void useBake(int size, float time) {
        bake.use();
        bakeSize.set(size, size);
        bakeTime.set(time);
    }

    /** The shadow map's program in use, for a layer ({@code uLayer}), a motion ({@code uMotion}), a map size, the eye
     * and the direction towards the sun. */
    void useShadow(Vector4fc layer, Vector4fc motion, int size, Vector3fc eye, Vector3fc toSun) {
        shadow.use();
        shadowEye.set(eye);
        shadowSun.set(toSun);
        shadowLayer.set(layer);
        shadowMotion.set(motion);
        shadowSize.set(size, size);
    }

    /** The march's program in use: the grid's size, this frame's slot, whether every texel is marched. */
    void useMarch(Vector4fc layer, Vector4fc motion, int gridWidth, int gridHeight, int[] slot, boolean every) {
        march.use();
        marchLayer.set(layer);
        marchMotion.set(motion);
        marchGrid.set(gridWidth, gridHeight, slot[0], slot[1]);
        marchEvery.set(every ? 1 : 0);
    }

    /** The resolve's program in use, with the previous frame's world-to-clip matrix. */
    void useResolve(Matrix4fc previous, int gridWidth, int gridHeight, int[] slot, boolean every) {
        resolve.use();
        resolvePrevious.set(previous);
        resolveGrid.set(gridWidth, gridHeight, slot[0], slot[1]);
        resolveEvery.set(every ? 1 : 0);
    }

    /** The composite's program in use, for the sky's pixels or the surfaces'. */
    void useComposite(int gridWidth, int gridHeight, boolean sky) {
        composite.use();
        compositeGrid.set(gridWidth, gridHeight);
        compositeSky.set(sky ? 1 : 0);
    }
}

package org.openworld.engine;

import java.nio.FloatBuffer;
import org.joml.Matrix4f;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.core.Owned;
import org.openworld.engine.core.PassView;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.core.World;
import org.openworld.engine.environment.CloudShadow;
import org.openworld.engine.environment.Exposure;
import org.openworld.engine.environment.SkyMaps;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.environment.SunShadow;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.gl.CubeMapTexture;
import org.openworld.engine.gl.FrameUniforms;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.SharedBlock;
import org.openworld.engine.gl.SharedTexture;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.Texture3D;

/**
 * What every shader of a pass can read without its system binding it (docs/design.md, "Passes"): the frame uniform
 * block ({@code shaders/common/frame.glsl}: the pass camera, the sun, the exposure, the clock, the target's size),
 * the sky's aerial-perspective volume and environment map, the sun's shadow maps with their block, and the clouds'
 * shadow map with its block. A world without a sky gets neutral stand-ins (clear air, a uniform sky as bright as the
 * noon sun's ambient light), and a frame whose shadow maps are not drawn (or a world without volumetric clouds) gets
 * a map that shadows nothing, so a shader never branches on what the
 * scene has.
 */
final class SharedBindings {

    private final FrameUniforms frameUniforms;
    private final SkyMaps neutralSky;
    private final SunShadow noShadow;
    private final CloudShadow noClouds;

    /** Makes the frame block and the stand-ins, handing them to {@code owned} (the engine's). */
    SharedBindings(GlContext gl, Owned owned) {
        frameUniforms = owned.own("frame", new FrameUniforms(gl));
        neutralSky = neutralSky(gl, owned);
        noShadow = owned.own("noShadow", SunShadow.none(gl));
        noClouds = owned.own("noCloudShadow", CloudShadow.none(gl));
    }

    /**
     * Writes the frame block for one view of a pass (its camera, and the viewer's eye as {@code viewerPos}) and binds
     * the shared textures and blocks: the sky's, or the stand-ins; the sun's shadow once its owner has had this
     * frame's turn (drawn its maps, or kept the last frame's; its block says none while the sun is down), else none
     * (no system casts shadows or it is switched off; and a map being drawn must not be bound for reading).
     *
     * @return whether the sun's shadow maps were bound, not the stand-in ({@link RenderContext#sunShadowed})
     */
    boolean bind(World world, PassView view, PassView viewer, double simTime, long frame, boolean shadowReady) {
        frameUniforms.write(frameValues(world, view, viewer, simTime, frame));
        SkyMaps maps = world.findResource(SkyMaps.class).orElse(neutralSky);
        maps.aerialPerspective().bind(SharedTexture.AERIAL_PERSPECTIVE.unit());
        maps.environment().bind(SharedTexture.ENVIRONMENT.unit());
        SunShadow shadow = shadowReady ? world.findResource(SunShadow.class).orElse(noShadow) : noShadow;
        shadow.map().bind(SharedTexture.SHADOW_MAP.unit());
        shadow.block().bindBase(SharedBlock.SHADOW.binding());
        CloudShadow clouds = world.findResource(CloudShadow.class).orElse(noClouds);
        clouds.map().bind(SharedTexture.CLOUD_SHADOW_MAP.unit());
        clouds.block().bindBase(SharedBlock.CLOUD_SHADOW.binding());
        return shadow != noShadow;
    }

    /** The block for one view of a pass; {@code viewer} is the MAIN camera's, given to every pass as the viewer. */
    private static FrameUniforms.Values frameValues(World world, PassView view, PassView viewer, double simTime,
                                                    long frame) {
        ViewCamera camera = view.camera();
        Sun sun = world.findResource(Sun.class).orElse(Sun.NOON);
        Exposure exposure = world.findResource(Exposure.class).orElse(Exposure.NONE);
        return new FrameUniforms.Values(new Matrix4f(camera.view()), new Matrix4f(camera.projection()),
                camera.position(), camera.near(), camera.far(), sun.direction(), sun.color(), sun.ambient(),
                exposure.scale(), exposure.scotopic(), simTime, world.resource(TimeOfDay.class).hours(), frame, view.target().width(),
                view.target().height(), viewer.camera().position(), sun.sky().shaderFactors());
    }

    /** No air (nothing scattered in, everything transmitted) and a uniform sky as bright as the noon sun's ambient. */
    private static SkyMaps neutralSky(GlContext gl, Owned owned) {
        FloatBuffer clearAir = MemoryUtil.memAllocFloat(4).put(0).put(0).put(0).put(1).flip();
        try {
            Texture3D air = owned.own("neutralAir",
                    Texture3D.of(gl, 1, 1, 1, Format.RGBA16F, Sampling.LINEAR_CLAMP, clearAir));
            return new SkyMaps(air, owned.own("neutralSky",
                    CubeMapTexture.fromDirections(gl, 1, d -> Sun.NOON.ambient())));
        } finally {
            MemoryUtil.memFree(clearAir);
        }
    }
}

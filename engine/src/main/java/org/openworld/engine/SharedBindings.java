package org.openworld.engine;

import java.util.Collection;
import java.util.EnumMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import org.joml.Matrix4f;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.Owned;
import org.openworld.engine.core.PassView;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SharedResource;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.core.World;
import org.openworld.engine.environment.Exposure;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.gl.FrameUniforms;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.GlTexture;
import org.openworld.engine.gl.GpuBuffer;
import org.openworld.engine.gl.SharedBlock;
import org.openworld.engine.gl.SharedTexture;
import org.openworld.engine.origin.RenderOrigin;

/**
 * What every shader of a pass can read without its system binding it (docs/design.md, "Passes"): the frame uniform
 * block ({@code shaders/common/frame.glsl}: the pass camera and the viewer, from the {@link RenderOrigin}, the sun,
 * the exposure, the clock, the target's size) and the world's {@link SharedResource}s (the sky's maps, the sun's
 * shadow). Before them it binds a stand-in for every {@link SharedTexture} and {@link SharedBlock}
 * ({@link SharedTexture#standIn}: clear air, a uniform sky, a shadow map under which everything is lit), so a shader
 * never branches on what the scene has.
 */
final class SharedBindings {

    private final FrameUniforms frameUniforms;
    private final Map<SharedTexture, GlTexture> textureStandIns = new EnumMap<>(SharedTexture.class);
    private final Map<SharedBlock, GpuBuffer> blockStandIns = new EnumMap<>(SharedBlock.class);
    /** What the owners of passes write that their pass has not yet drawn this frame (the sun's shadow maps). */
    private final Set<Class<?>> held = new HashSet<>();

    /**
     * Makes the frame block and the stand-ins, handing them to {@code owned} (the engine's), and gives the world a
     * render origin with the default step (the terrain, if any, replaces it with its tile's).
     */
    SharedBindings(GlContext gl, Owned owned, World world) {
        world.setResource(new RenderOrigin(RenderOrigin.DEFAULT_STEP));
        frameUniforms = owned.own("frame", new FrameUniforms(gl));
        for (SharedTexture texture : SharedTexture.values()) {
            textureStandIns.put(texture, owned.own("standIn." + texture.sampler(), texture.standIn(gl)));
        }
        for (SharedBlock block : SharedBlock.values()) {
            GpuBuffer standIn = block.standIn(gl);
            if (standIn != null) {
                blockStandIns.put(block, owned.own("standIn." + block.block(), standIn));
            }
        }
    }

    /** At a frame's start: what the owners of passes write is held back until their pass has had its turn. */
    void beginFrame(Collection<EngineSystem> owners) {
        held.clear();
        owners.forEach(owner -> held.addAll(owner.spec().writes()));
    }

    /** An owner's pass has had its turn (it may have kept the last frame's maps): what it writes is shared from now. */
    void release(Set<Class<?>> written) {
        held.removeAll(written);
    }

    /**
     * The viewer's view for this frame, {@code camera} (the {@link Camera}'s, as the anti-aliasing may have moved it),
     * and the render origin moved to it: every pass of the frame measures positions from there.
     */
    PassView viewer(World world, ViewCamera camera, Framebuffer target) {
        world.resource(RenderOrigin.class).follow(camera.exactPosition().x(), camera.exactPosition().z());
        return new PassView(camera, target);
    }

    /**
     * Writes the frame block for one view of a pass (its camera, and the viewer's eye as {@code viewerPos}) and binds
     * the stand-ins, then over them every shared resource of the world but those held back (written by the owner of
     * a pass that has not had its turn this frame: a map being drawn must not be bound for reading).
     *
     * @return the classes of the shared resources bound ({@link RenderContext#shares})
     */
    Set<Class<?>> bind(World world, PassView view, PassView viewer, double simTime, long frame) {
        frameUniforms.write(frameValues(world, view, viewer, simTime, frame));
        textureStandIns.forEach((texture, standIn) -> standIn.bind(texture.unit()));
        blockStandIns.forEach((block, standIn) -> standIn.bindBase(block.binding()));
        Set<Class<?>> bound = new HashSet<>();
        for (SharedResource resource : world.resources(SharedResource.class)) {
            if (!held.contains(resource.getClass())) {
                resource.bindShared();
                bound.add(resource.getClass());
            }
        }
        return bound;
    }

    /** The block for one view of a pass; {@code viewer} is the MAIN camera's, given to every pass as the viewer. */
    private static FrameUniforms.Values frameValues(World world, PassView view, PassView viewer, double simTime,
                                                    long frame) {
        ViewCamera camera = view.camera();
        RenderOrigin origin = world.resource(RenderOrigin.class);
        Sun sun = world.findResource(Sun.class).orElse(Sun.NOON);
        Exposure exposure = world.findResource(Exposure.class).orElse(Exposure.NONE);
        return new FrameUniforms.Values(camera.viewFrom(origin.x(), origin.z()), new Matrix4f(camera.projection()),
                camera.positionFrom(origin.x(), origin.z()), camera.near(), camera.far(), sun.direction(), sun.color(),
                sun.ambient(),
                exposure.scale(), exposure.scotopic(), simTime, world.resource(TimeOfDay.class).hours(), frame, view.target().width(),
                view.target().height(), viewer.camera().positionFrom(origin.x(), origin.z()),
                origin.x() / origin.step(), origin.z() / origin.step(), origin.step(), sun.sky().shaderFactors());
    }
}

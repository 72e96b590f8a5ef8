package org.openworld.engine.core;

import java.util.Set;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.Framebuffer;

/**
 * What a system gets in {@link EngineSystem#render}: the world, the camera of the pass being drawn, the frame's draw
 * statistics and the pass's target. The frame uniform block ({@code shaders/common/frame.glsl}) already holds this
 * pass's camera, and the target is bound.
 *
 * @param world  the shared world
 * @param camera this pass's camera
 * @param stats  draw calls and triangles, counted by {@code Mesh}
 * @param target the framebuffer this pass draws into (the scene target in MAIN and OVERLAY), bound; a system that
 *               binds another one (the water copying the scene) binds this one back
 * @param shared the classes of the {@link SharedResource}s bound for this pass; the others' stand-ins are bound
 */
public record RenderContext(World world, ViewCamera camera, DrawStats stats, Framebuffer target,
                            Set<Class<?>> shared) {

    /**
     * Whether the world's {@code type} is bound for this pass rather than its stand-in. False for the sun's shadow
     * ({@code shaders/common/shadow.glsl}): a map that shadows nothing is bound, and a program compiled with
     * {@code SUN_UNSHADOWED}, which skips the lookup, draws the same picture for less.
     */
    public boolean shares(Class<? extends SharedResource> type) {
        return shared.contains(type);
    }
}

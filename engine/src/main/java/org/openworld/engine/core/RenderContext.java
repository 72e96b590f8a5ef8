package org.openworld.engine.core;

import org.openworld.engine.gl.DrawStats;

/**
 * What a system gets in {@link EngineSystem#render}: the world, the camera of the pass being drawn, and the frame's
 * draw statistics. The frame uniform block ({@code shaders/common/frame.glsl}) already holds this pass's camera.
 *
 * @param world  the shared world
 * @param camera this pass's camera
 * @param stats  draw calls and triangles, counted by {@code Mesh}
 * @param width  width of the scene target, pixels (a SHADOW or REFLECTION owner knows its own target's size)
 * @param height height of the scene target, pixels
 */
public record RenderContext(World world, ViewCamera camera, DrawStats stats, int width, int height) {
}

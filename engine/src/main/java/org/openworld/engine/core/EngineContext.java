package org.openworld.engine.core;

import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.ShaderSources;
import org.openworld.engine.settings.Settings;

/**
 * What a system gets in {@link EngineSystem#init}: the GL context to create objects with (they count against it),
 * the world, the shader files and the settings.
 *
 * @param gl       the context; every GL object is created with it
 * @param world    the shared world
 * @param shaders  where GLSL files are read from
 * @param settings the settings resource (also in the world)
 */
public record EngineContext(GlContext gl, World world, ShaderSources shaders, Settings settings) {
}

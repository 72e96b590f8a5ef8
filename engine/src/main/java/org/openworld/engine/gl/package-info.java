/**
 * Thin owners of OpenGL objects, one class per kind, each {@link java.lang.AutoCloseable} and counted in
 * {@link org.openworld.engine.gl.GlObjects} so tests can prove that shutdown frees everything (CONTRIBUTING.md, "Owners").
 *
 * <ul>
 *   <li>{@link org.openworld.engine.gl.GlContext}: the one way to get a context: a window, or headless through
 *       GLFW's null platform with EGL, then a hidden X11 window (docs/design.md, "Headless rendering").</li>
 *   <li>{@link org.openworld.engine.gl.ShaderPreprocessor}: {@code #include} with {@code #line} bookkeeping, so a
 *       driver's {@code 2:14(7): error} is reported as {@code shaders/common/fog.glsl:14}.</li>
 *   <li>{@link org.openworld.engine.gl.ShaderProgram}: typed uniform handles resolved at link time
 *       (CONTRIBUTING.md, "Uniforms"); {@link org.openworld.engine.gl.ShaderLibrary} reloads all programs in dev mode.</li>
 *   <li>{@link org.openworld.engine.gl.FrameUniforms}: the std140 block every shader includes from
 *       {@code shaders/common/frame.glsl}.</li>
 *   <li>{@link org.openworld.engine.gl.GpuTimers}: {@code GL_TIME_ELAPSED} queries read a frame or two late so
 *       timing never stalls the pipeline.</li>
 * </ul>
 */
package org.openworld.engine.gl;

/**
 * Thin owners of OpenGL objects, one class per kind, each {@link java.lang.AutoCloseable} and counted in
 * {@link org.openworld.engine.gl.GlObjects} (names made and deleted through {@code GlObjects.create/delete}, so
 * closing twice deletes once), so tests can prove that shutdown frees everything.
 *
 * <ul>
 *   <li>{@link org.openworld.engine.gl.GlContext}: the one way to get a context: a window, or headless through
 *       EGL's device platform ({@link org.openworld.engine.gl.EglDevice}: a surfaceless context on a GPU or Mesa's
 *       software device, no display and no libGL), then GLFW's null platform with EGL, then a hidden X11 window,
 *       or one of them as a {@link org.openworld.engine.gl.HeadlessChoice} says; with {@code debug}
 *       ({@code --dev}) a debug context whose driver messages are printed on stderr.</li>
 *   <li>{@link org.openworld.engine.gl.GlTexture}: what every texture shares: name, target, size, one
 *       {@link org.openworld.engine.gl.Format} (the texel format, also {@link org.openworld.engine.gl.Framebuffer}'s)
 *       and one {@link org.openworld.engine.gl.Sampling} (filters and wrap, written once at creation). Its kinds:
 *       {@link org.openworld.engine.gl.Texture2D}, {@link org.openworld.engine.gl.Texture3D},
 *       {@link org.openworld.engine.gl.TextureArray}, {@link org.openworld.engine.gl.CubeMapTexture},
 *       {@link org.openworld.engine.gl.DepthTextureArray}.</li>
 *   <li>{@link org.openworld.engine.gl.TextureMemory}: the bytes a context's textures hold, now and at most, counted
 *       by {@code GlTexture} as storage is made and closed: width × height × layers ×
 *       {@link org.openworld.engine.gl.Format#bytesPerTexel()}, summed over the mip levels (a full chain adds about a
 *       third: 1 + 1/4 + 1/16 + ... = 4/3). OpenGL cannot be asked and most drivers report no memory, so this is the
 *       figure every driver has ({@code bench}'s {@code texturePeakMib}); a driver's padding and alignment come on
 *       top.</li>
 *   <li>{@link org.openworld.engine.gl.ShaderPreprocessor}: {@code #include}, and where every line of the expanded
 *       text came from, so that {@code ShaderLog} reports a driver's {@code 0:123(26): error} (Mesa; NVIDIA's and
 *       AMD's/Intel's forms too) as {@code shaders/common/fog.glsl:15:26: error}. The line alone finds the file:
 *       Mesa prints source string 0 for most semantic errors.</li>
 *   <li>{@link org.openworld.engine.gl.ShaderProgram}: typed uniform handles resolved at link time;
 *       {@link org.openworld.engine.gl.ShaderLibrary} reloads all programs in dev mode.</li>
 *   <li>{@link org.openworld.engine.gl.FrameUniforms}: the std140 block every shader includes from
 *       {@code shaders/common/frame.glsl}.</li>
 *   <li>{@link org.openworld.engine.gl.GpuTimers}: {@code GL_TIME_ELAPSED} queries read a frame or two late so
 *       timing never stalls the pipeline; each span is also a debug group of the same label.</li>
 *   <li>{@link org.openworld.engine.gl.GlDebug}: {@code KHR_debug}, decided once per context: object labels
 *       ({@link org.openworld.engine.gl.Labelled}, {@code terrain.heights}), debug groups ({@code main.terrain}) and
 *       driver messages; no-ops where the driver lacks it.</li>
 * </ul>
 *
 * <p>Who closes what: a system hands each object it makes to {@code EngineContext.own(role, thing)}, which labels it
 * {@code system.role}; the engine closes it with the system, newest first ({@code core.Owned}).
 */
package org.openworld.engine.gl;

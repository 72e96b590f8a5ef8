/**
 * The light every lit shader shares, as world resources written by the systems that model it and bound by the
 * engine before each pass: {@link org.openworld.engine.environment.TimeOfDay} (the clock),
 * {@link org.openworld.engine.environment.Sun} (direction, direct and ambient light),
 * {@link org.openworld.engine.environment.Exposure} (scene light to the tone mapper),
 * {@link org.openworld.engine.environment.SkyMaps} (the sky around the scene and the air between the eye and a point:
 * {@code shaders/common/environment.glsl}, {@code fog.glsl}) and
 * {@link org.openworld.engine.environment.SunShadow} (where the sun cannot reach: {@code shaders/common/shadow.glsl}).
 *
 * <p>The sky system writes the first four, the shadow system the last. Without them the engine lights the world with
 * a high white sun, clear air and no shadows, so a system can be read and tested alone.
 */
package org.openworld.engine.environment;

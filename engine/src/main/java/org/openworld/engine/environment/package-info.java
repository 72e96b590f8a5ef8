/**
 * The light every lit shader shares, as world resources written by the systems that model it and bound by the
 * engine before each pass: {@link org.openworld.engine.environment.TimeOfDay} (the clock),
 * {@link org.openworld.engine.environment.Sun} (direction, direct and ambient light, and the light of the sky and of
 * the sunlit ground on any normal as nine spherical-harmonic factors,
 * {@link org.openworld.engine.environment.SkyIrradiance}: {@code shaders/common/frame.glsl}'s skyIrradiance),
 * {@link org.openworld.engine.environment.Exposure} (scene light to the tone mapper),
 * {@link org.openworld.engine.environment.SkyMaps} (the sky around the scene and the air between the eye and a point:
 * {@code shaders/common/environment.glsl}, {@code fog.glsl}) and
 * {@link org.openworld.engine.environment.SunShadow} (where the sun cannot reach: {@code shaders/common/shadow.glsl}).
 *
 * <p>The sky system writes the first four, the shadow system the last. Without them the engine lights the world with
 * a high white sun, clear air and no shadows, so a system can be read and tested alone.
 *
 * <p>Beside the light, two facts about the world's surface that one system knows and others build on, so that no
 * system need import another's settings: {@link org.openworld.engine.environment.WaterLevel} (the water system writes
 * it, the minimap reads it) and {@link org.openworld.engine.environment.SnowLine} (the terrain writes it, in metres).
 */
package org.openworld.engine.environment;

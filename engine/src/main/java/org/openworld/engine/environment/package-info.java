/**
 * The shared environment resources: {@link org.openworld.engine.environment.TimeOfDay},
 * {@link org.openworld.engine.environment.Sun} (direction, direct and ambient light) and
 * {@link org.openworld.engine.environment.Fog} (height-dependent exponential fog, applied identically in every pass
 * by {@code shaders/common/fog.glsl}).
 *
 * <p>{@link org.openworld.engine.environment.DaylightSystem} is the first-order model used until a sky system
 * computes these from atmospheric scattering (paper section 3.1): solar position from the hour angle, and
 * sunlight reddened by the Kasten–Young air mass through a per-channel optical depth. Its limit is the one the
 * paper warns of: three RGB "wavelengths" and no scattering into the view, so dawn and dusk colours are rough.
 */
package org.openworld.engine.environment;

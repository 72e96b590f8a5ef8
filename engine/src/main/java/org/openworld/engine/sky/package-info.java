/**
 * The sky (paper sections 2.3 and 3.1, figures 5, 8 and 9): sunlight scattered by the air, the clouds, and the light
 * the sky gives the world. Page: docs/sky.md, with every measurement and figure.
 *
 * <p><b>Formula.</b> Light of wavelength λ reaching the eye from direction v is the sunlight scattered into the view
 * ray at every point p on it, dimmed on the way in and out:
 * {@code L(λ) = ∫ Σ_k β_k(λ) ρ_k(h(p)) P_k(θ) E_sun T(p→sun) T(eye→p) ds}, k over Rayleigh (β ∝ λ⁻⁴, phase
 * 3/16π (1 + cos²θ)) and Mie (aerosols, grey, forward-peaked Cornette–Shanks phase), densities ρ falling
 * exponentially with height, transmittance {@code T = exp(−∫ extinction)}, ozone absorbing but not scattering.
 * {@link org.openworld.engine.sky.AtmosphereSettings} chooses the solution: {@code SINGLE}, the paper's equations 3
 * and 4 as nested sums (outer along the view ray, inner towards the sun), light scattered once; or {@code MULTIPLE}
 * (default), Hillaire 2020: a transmittance table replaces the inner sum and a multiple-scattering table adds every
 * higher order as an isotropic source {@code Ψ_ms = L₂ / (1 − f_ms)}, which lights the twilight sky. The constants
 * are Earth's ({@code PHYSICAL}) or the paper's, after O'Neil 2005 ({@code NORMALISED}, heights in units of the
 * shell's thickness: {@link org.openworld.engine.sky.Atmosphere}). All of it is spectral:
 * {@link org.openworld.engine.sky.Spectrum} samples 400–750 nm (8 by default) and integrates against the CIE 1931
 * colour-matching functions to linear sRGB, because extinction is not linear in λ (paper 3.1).
 *
 * <p><b>Data path.</b> The sky is the same for every eye at one altitude under one sun elevation, laid out relative
 * to the sun's azimuth, so the CPU builds tables when the sun or the eye moved enough
 * ({@link org.openworld.engine.sky.SunTables#staleFor}), on a worker thread:
 * <ol>
 *   <li>the dome, {@link org.openworld.engine.sky.SkyView} (192 × 108 directions, denser at the horizon);</li>
 *   <li>the aerial perspective, {@link org.openworld.engine.sky.AerialPerspective} (32 × 32 directions × 32
 *       distances up to 64 km; with {@code atmosphere.fog=simple} the paper's distance fog in the same table);</li>
 *   <li>the light, {@link org.openworld.engine.sky.SkyLight}: the sun's colour at the eye, and the sky's irradiance
 *       on any normal as order-2 spherical harmonics, with the sunlit ground below as one bounce;
 *       {@link org.openworld.engine.sky.NightLight} adds airglow, the moon
 *       ({@link org.openworld.engine.sky.MoonPosition}) and the moonlit sky;</li>
 *   <li>on the GL thread, in the update: the {@link org.openworld.engine.sky.SkyPanorama} (two hemi-octahedral
 *       squares of 576², the direction projected onto the octahedron {@code d / (|x| + |y| + |z|)}) drawn from the
 *       tables and the {@link org.openworld.engine.sky.CloudField}, and the environment map from it; both shared
 *       with every pass as {@link org.openworld.engine.environment.SkyMaps}.</li>
 * </ol>
 * The sky pass then draws a full-screen triangle at the far plane as the frame's background
 * ({@link org.openworld.engine.core.Layer#BACKGROUND}), depth-tested, so only the pixels no surface covers are
 * shaded, each with one panorama lookup, plus what cannot be interpolated: the clouds' edge and the sun's disc.
 * {@link org.openworld.engine.sky.Adaptation} exposes the picture for the light of the moment, from noon to a
 * moonless night (ten decades), with the rods' shift towards grey-blue; the
 * {@link org.openworld.engine.sky.StarField} draws the {@link org.openworld.engine.sky.StarCatalogue} one pixel a
 * star when they would show. Units are display units, 1 = a white surface facing the sun above the atmosphere.
 *
 * <p><b>Clouds</b> (paper 2.3). {@link org.openworld.engine.sky.CloudField}: random phases with amplitude 1/f over
 * two axes of space and one of time, one inverse 3D DFT: a density that tiles in space and loops in time, mapped
 * onto the dome four ways ({@link org.openworld.engine.sky.CloudSettings.Mapping}, figure 5).
 *
 * <p><b>Files.</b> {@link org.openworld.engine.sky.SkySystem} (the system), the integrators and tables above,
 * {@code shaders/sky/} ({@code atmosphere.glsl}: the tables' lookups, shared with {@code shaders/common/fog.glsl};
 * {@code panorama.frag}, {@code sky.frag}, {@code stars.frag}).
 *
 * <p><b>Cost and limits</b> (docs/sky.md, "Cost" and "Limits"): a panorama refresh twice a simulated second, the sky
 * pass in proportion to the sky one sees. The clouds are a flat, single-scattering layer with no volume and no
 * shadows on the ground; the ground albedo is one grey; the moon casts no shadows, the stars have no colours; the
 * tables assume the eye at the altitude they were built for, rebuilt every 100 m of climb.
 */
package org.openworld.engine.sky;

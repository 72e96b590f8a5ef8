/**
 * The sky (paper sections 2.3 and 3.1, figures 5, 8 and 9): sunlight scattered by the air, the clouds, and the light
 * the sky gives the world.
 *
 * <p><b>Scattering.</b> Light of wavelength λ reaching the eye from direction v is the sunlight scattered into the
 * view ray at every point p on it, dimmed on the way in and out:
 * {@code L(λ) = ∫ Σ_k β_k(λ) ρ_k(h(p)) P_k(θ) E_sun T(p→sun) T(eye→p) ds}, k over Rayleigh (β ∝ λ⁻⁴, phase
 * 3/16π (1 + cos²θ)) and Mie (aerosols, grey, forward-peaked Cornette–Shanks phase), densities ρ falling
 * exponentially with height (8 km and 1.2 km scale heights), transmittance {@code T = exp(−∫ extinction)}, with ozone
 * absorbing but not scattering. {@link org.openworld.engine.sky.AtmosphereSettings} chooses how it is solved:
 * <ul>
 *   <li>{@code SINGLE}: the paper's equations 3 and 4 as written, nested sums: an outer sum of points along the
 *       view ray, and at each an inner sum towards the sun for its optical depth; only light scattered once.
 *       Cost per direction: outer × inner × wavelengths. Its limit is the paper's own: with the sun below the
 *       horizon the lit air is far away and dawn and dusk go darker and greyer (figure 9 a and f), though with
 *       Earth's constants not black: at −4° the zenith is 1.7 times darker than with multiple scattering.</li>
 *   <li>{@code MULTIPLE} (default): Hillaire 2020, "A Scalable and Production Ready Sky and Atmosphere Rendering
 *       Technique": a transmittance table (altitude × sun angle) replaces the inner sum, and a multiple-scattering
 *       table adds every higher order as an isotropic source {@code Ψ_ms = L₂ / (1 − f_ms)} (the second order
 *       times the geometric series of the fraction re-scattered), which lights the twilight sky.</li>
 * </ul>
 * <p><b>Constants</b> ({@code atmosphere.constants}, {@link org.openworld.engine.sky.Atmosphere}). {@code PHYSICAL}
 * (default): Earth's, above. {@code NORMALISED}: the paper's, after O'Neil 2005 (GPU Gems 2 chapter 16, the paper's
 * reference 2): heights and path lengths in units of the shell's thickness H0, x = h/H0 from 0 to 1, densities
 * e^(−x/0.25) (Rayleigh) and e^(−x/0.1) (Mie), optical depth t = 4π·K·λ⁻⁴·∫ρ d(s/H0) with O'Neil's K_R = 0.0025
 * (λ in µm) and K_M = 0.0010, no ozone, the same sun E_sun = 1 (O'Neil's hand-tuned sun intensity and exposure
 * are the scene's automatic exposure here). H0 is OpenWorld's 100 km shell, 1.6 % of the planet's radius rather
 * than O'Neil's 2.5 %: the paper gives neither, and the one shell keeps every table's geometry. Chosen as O'Neil
 * published them, untuned: the noon zenith is blue and half as bright as the default's (0.48), the horizon under
 * a setting sun orange-yellow. What they do not give is figure 9's dark dawn and dusk: with the sun 2°, 4° and 6°
 * below the horizon the zenith is 4.1, 8.9 and 36 times as bright as the default sky's ({@code TwilightTest}). The
 * Rayleigh air thins with a 25 km scale height here against Earth's 8 km, so the air above the planet's shadow
 * (15 km up at the zenith with the sun 4° down) is still dense and lit. The paper's dark twilight must come from
 * elsewhere, its fixed exposure or an approximation of the sun's optical depth it does not describe; its nested
 * sums on its own constants do not make it.
 * <p>All of it is spectral: {@link org.openworld.engine.sky.Spectrum} samples 400–750 nm (the paper found 6 samples the
 * least that works; 8 by default) and integrates them against the CIE 1931 colour-matching functions to XYZ and
 * then linear sRGB, white-balanced to the sun above the air. Mixing three RGB "wavelengths" instead gets the colours
 * wrong, because extinction is not linear in λ (paper 3.1). {@link org.openworld.engine.sky.SkyPicture} measures the
 * paper's findings (mean CIEDE2000 of the sun's half of the dome to a finely sampled reference): 6 wavelengths are
 * under 2 at noon and at sunset in the default sky (1.78, 1.17; the paper's single-scattering sunset 2.16, where 8
 * are needed), but with Earth's constants the sums need about 16 samples, not the paper's 2 (13 to 16 off), because
 * the air thins by e^12.5 across the 100 km shell where the paper's normalised height thinned it by e^4. Figure 8's
 * Rayleigh-only and Mie-only skies are {@code atmosphere.component}.
 *
 * <p><b>Tables, not per-pixel integrals.</b> The sky is the same for every eye at one altitude under one sun
 * elevation, laid out relative to the sun's azimuth; so the CPU computes, when the sun or the eye moved enough
 * ({@link org.openworld.engine.sky.SunTables#staleFor}): the dome ({@link org.openworld.engine.sky.SkyView}, 192 ×
 * 108 directions, denser at the horizon: the paper's per-vertex dome evaluation), the aerial perspective for the
 * terrain ({@link org.openworld.engine.sky.AerialPerspective}, 32 × 32 directions × 32 distances up to 64 km; or,
 * with {@code atmosphere.fog=simple}, the paper's distance fog in the same table: transmittance e^(−d/D) and the
 * horizon's colour at each azimuth times 1 − e^(−d/D), no marching) and
 * the light ({@link org.openworld.engine.sky.SkyLight}: the sun's colour at the eye from the transmittance, the
 * sky's irradiance on the ground, and on any normal as order-2 spherical harmonics projected from the sky-view table
 * turned to the sun's azimuth, with the sunlit ground below as one bounce: albedo · (sun + sky on level ground) / π
 * of radiance from the lower hemisphere, whose irradiance is exactly that times π(1 − n_y)/2; re-projected when the
 * tables change or the sun moves 0.1°, about 4600 table reads). The GPU only looks them up. Units throughout are
 * display units, 1 = a white surface facing the sun above the atmosphere; an automatic exposure adapts to the light
 * of the moment. The night's radiance (10⁻⁹ to 10⁻⁶) is below a half float's normal range (6·10⁻⁵): the dome
 * table holds full floats, and the panorama its radiance relative to the light on the ground.
 *
 * <p><b>Twilight and night.</b> From sunset to a moonless night the light on the ground falls by ten decades.
 * {@link org.openworld.engine.sky.Adaptation} shows a white surface in the light E at B = max(√E, 0.075 · E^0.03):
 * the day's square root down to the sun 1° below the horizon, then a night floor that falls by only 0.93 per decade,
 * and shifts the colours towards the rods' grey-blue as they take over (the Purkinje shift of Jensen et al. 2001,
 * in {@code shaders/common/color.glsl}). {@link org.openworld.engine.sky.NightLight} adds the night's light to the
 * sky's, on the ground through the same harmonics: the airglow of a moonless sky (21.6 mag/arcsec²), the moon
 * ({@link org.openworld.engine.sky.MoonPosition}: on the ecliptic at the elongation of its age, its light by Allen's
 * magnitude law, its disc lit where it faces the sun) and the moonlit sky. 4570 stars
 * ({@link org.openworld.engine.sky.StarCatalogue}, synthesised on the star-count law log N(&lt;m) = 0.6 + 0.51 m)
 * are drawn one pixel each over the sky ({@link org.openworld.engine.sky.StarField}) when they would show. Cost: none
 * by day; at night the stars' one draw and the shift's few operations per pixel (docs/sky.md, "Twilight and night").
 *
 * <p><b>Clouds</b> (paper 2.3). {@link org.openworld.engine.sky.CloudField}: random phases with amplitude 1/f over
 * two axes of space and one of time, one inverse 3D DFT: a density that tiles in space and loops in time. Mapped
 * onto the dome four ways ({@link org.openworld.engine.sky.CloudSettings.Mapping}, figure 5): spherical angles
 * (squeezed at the horizon), the same with fog, perspective-corrected onto a layer at an altitude (repeats show
 * towards the horizon), and that with horizon fog (the default).
 *
 * <p><b>Each pixel once, and cheaply.</b> The sky is the frame's background
 * ({@link org.openworld.engine.core.Layer#BACKGROUND}): it draws after the terrain and the trees, a full-screen
 * triangle on the far plane with the depth test {@code LEQUAL} and no depth writes, so every pixel a surface covers
 * fails the depth test before its fragment shader runs (early depth rejection, which llvmpipe does too while the
 * shader neither writes depth nor discards), and the sky costs in proportion to the sky one sees. What it does shade
 * is one lookup: the dome, the distant ground and the clouds are evaluated not per pixel but per texel of a
 * {@link org.openworld.engine.sky.SkyPanorama} (two hemi-octahedral squares of 576², the direction projected onto
 * the octahedron {@code d / (|x| + |y| + |z|)} and its half turned by 45° to fill a square with the zenith at the
 * centre and the horizon on the border: no trigonometry per pixel), redrawn in the update when
 * the tables or the cloud settings changed, the sun moved 0.1° or the clouds drifted for half a second; the
 * environment map is drawn from it then too. Two values cannot be interpolated from a panorama without losing what
 * they look like, so they stay per pixel: the cloud's edge, a smoothstep of the interpolated density (a bilinear
 * opacity shows the texel grid), and the sun's disc with its limb darkening, as sharp as the screen. Cost on the
 * 2-core llvmpipe machine at 1280 × 720: a refresh 21–23 ms, twice a simulated second; the sky pass 8.3 ms in a view
 * where the sky covers half the picture, of which 3.4 ms is the full-screen triangle's rasterisation and depth test
 * (the whole sky shader on every pixel cost 28.6 ms). Limit: clouds finer than a panorama texel (near the horizon,
 * under the fog) are averaged rather than aliased, and clouds move in steps of half a second, about a pixel overhead.
 *
 * <p><b>Limits.</b> The clouds are a flat, single-scattering layer with no volume and no shadows on the ground; the
 * ground albedo is one grey; the moon casts no shadows and has no glow around it, the stars no colours; and the
 * tables assume the eye at the altitude they were built for, rebuilt every 100 m of climb.
 */
package org.openworld.engine.sky;

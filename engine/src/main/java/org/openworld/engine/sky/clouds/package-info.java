/**
 * Volumetric clouds ({@code clouds.mode=volumetric}): the sky's cloud field ray-marched as a volume between two
 * altitudes over the curved Earth, lit by the sun and the sky, amortised over frames, and casting its shadow on
 * everything the sun lights. Shaders in {@code shaders/clouds/}; the settings are the sky's {@code clouds.*}
 * ({@link org.openworld.engine.sky.CloudSettings}); docs/sky.md, "Volumetric clouds", has pictures and the cost.
 *
 * <h2>Density</h2>
 * The layer lies between the spheres of radius R + base and R + base + thickness around a centre R = 6360 km below
 * the eye. At a point of height fraction h in it (0 base, 1 top), with the field F (a 3D DFT over two axes of space
 * and one of time, the sky's {@link org.openworld.engine.sky.CloudField} drawn again at the power 1/f³ from the same
 * seed: smoother, with the sky's phases, so its clouds stand where the layer's are) and the detail field D (the
 * sky's own, 1/f², 7 times finer, its time axis turned upright):
 * <pre>
 *   cover   = clamp((F(x/tile, z/tile, t) − threshold) / 1.5, 0, 1)      threshold: the field's (1 − cover) quantile
 *   shape   = clamp(cover + profile(h, type) − 1, 0, 1)                  CloudOptics.heightProfile: stratus .. cumulus
 *   e       = 0.45 · clamp(0.5 + 0.25 D, 0, 1)
 *   density = clamp((shape − e) / (1 − e), 0, 1)      σ = 0.04/m · density (a mean free path of 25 m at the core)
 * </pre>
 * The base field is read in 2D: each update draws it at the clouds' time into a texture of the same texels
 * ({@code clouds/bake.frag}), which read bilinearly gives the 3D field's trilinear value at half the texels. The wind
 * carries both fields ({@code clouds.wind-*}, the {@code Wind} the sky publishes), and the time axis
 * evolves them ({@code clouds.period}).
 *
 * <h2>Light</h2>
 * Along the view ray, 24 steps between where it enters and leaves the layer (cut at the scene's depth and at 60 km,
 * the first step jittered per pixel); empty space is crossed two steps at a time, back one at the first cloud, so
 * every sample is one of the 24. At each sample in a cloud, the optical depth τ towards the sun from three samples
 * 50, 180 and 450 m away, and the light scattered towards the eye with the albedo 1, integrated over the step as
 * S (1 − e^(−σ Δt)) (Hillaire 2016), where
 * <pre>
 *   S = π E_sun Σ_{i=0..2} 0.5^i p_i(μ) e^(−0.5^i τ) + mix(E_sky(down), E_sky(up), h)
 * </pre>
 * E_sun the sun's light at the eye (the atmosphere's transmittance table, {@code frame.sunColor}), p_i the dual-lobe
 * Henyey–Greenstein phase with its anisotropy times 0.5^i ({@link org.openworld.engine.sky.clouds.CloudOptics}: the
 * octaves of multiple scattering, Wrenninge et al. 2013), and E_sky the sky's irradiance from its harmonics (the
 * ground's bounce from below at the base, the sky from above at the top). The air between the eye and the cloud's
 * mean distance is added from the aerial-perspective table ({@code common/fog.glsl}).
 *
 * <h2>Amortised</h2>
 * The march runs on a grid of a quarter of the picture's width and height ({@link CloudTargets}), and each frame
 * marches one texel of every 2 × 2 block of it (1/64 of the pixels). The resolve reprojects the rest: each texel's
 * point, along its ray at the cloud distance its marched neighbour found, is looked up in the last frame's grid
 * through the last frame's view and projection, and the result clamped to the range of this frame's marched texels
 * around it, so that nothing that moved or appeared leaves a ghost (Schneider 2015, "The real-time volumetric
 * cloudscapes of Horizon Zero Dawn": one pixel in 16 per frame). A camera that cut (200 m or 20° in a frame), a new
 * size or new settings march every texel. The composite upsamples the grid over the picture, from the grid texels
 * marched against the same kind of pixel (sky or surface; the depth test picks the pixels), so a cloud stops at a
 * mountain's silhouette.
 *
 * <h2>Shadows</h2>
 * {@code clouds/shadow.frag} marches the sun's ray up through the layer from each texel of one tile of the field at
 * the cloud base (128², 12 steps, the base shape) into the {@link org.openworld.engine.environment.CloudShadow} map,
 * twice a simulated second and when the sun moves 0.2°. Every lit shader reads it through
 * {@code sunVisibility} ({@code common/shadow.glsl}, a shared texture and block the engine binds), so the ground,
 * the water, the trees and the snow are shadowed with one lookup, whoever draws them. The block holds the wind's
 * offset from the world's origin and each pass adds its own render origin (the frame block's), so the shadow stays
 * on the ground on the frame the origin steps, after the update wrote the block.
 *
 * <h2>Reflection and environment map</h2>
 * {@link org.openworld.engine.sky.clouds.CloudPanoramaMarch} marches the same rays from the viewer's eye in every
 * direction into a panorama in the sky's layout (128² a hemisphere, {@code clouds/panorama.frag}), one band of 8 rows
 * a frame (a whole panorama in 16 frames, 1 024 rays a frame against the picture's 14 400 at 1280 × 720), in the
 * frame's first pass; the water's reflection looks it up per sky pixel along its mirrored ray
 * ({@code clouds/reflection.frag}), and the sky's environment map per texel
 * ({@link org.openworld.engine.environment.CloudPanorama}).
 *
 * <h2>Limits</h2>
 * The reflection's and the environment map's clouds are seen from the eye, not from the water's point, at 0.7° to
 * 1.4° a texel; the environment map takes them at the sky's own refresh, one step late. The sun's light is the one at the eye, so the clouds darken when the sun sets at the
 * eye, not at their altitude. The composite knows sky from surface but not one surface's distance from another's,
 * so a cloud between two ridges is drawn over both. The cloud shadow takes the layer flat and the ground's point
 * carried to the base along the sun, at most 20 km away (the sun at least 3° up).
 */
package org.openworld.engine.sky.clouds;

/**
 * Reflective, transparent water to the horizon (paper section 3.3, figure 13): the paper's stencil method, and the
 * cleaner two-picture method its section 5 proposes, made physical. Page: {@code docs/water.md}.
 *
 * <p><b>The plane.</b> The water is the plane {@code y = water.level}, found per pixel: a full-screen triangle whose
 * fragment shader intersects the view ray with the plane ({@code t = (level − eye.y) / dir.y}) and writes the hit's
 * depth. It needs no mesh, so it reaches the horizon in every direction and never shows an edge.
 *
 * <p><b>The paper's method</b> ({@code water.method=STENCIL}), step by step: (1) at the start of MAIN, before anything
 * is drawn ({@code WaterSystem.beginPass}), the stencil is cleared to 0xFF and every opaque fragment then writes 0;
 * (2) the water plane writes 0xFF where it is the nearest surface, and
 * only its alpha, the reflectivity {@code water.alpha}; (3) the reflection pass draws the scene upside down (the
 * mirrored camera, front faces culled by the flipped winding) into a second framebuffer; (4) a full-screen quad of
 * that picture, where the stencil is 0xFF, blended by destination alpha:
 * {@code colour = reflection · α + ground · (1 − α)}. Alpha 0 shows the ground, 1 only the mirror (figure 13).
 * Its limits are the paper's: one alpha for every angle, and nothing clips the mirrored scene, so the lake bed shows
 * in the reflection.
 *
 * <p><b>The Fresnel method</b> (default, {@code water.method=FRESNEL}):
 * <ul>
 *   <li>Reflection: the viewer mirrored in the plane, {@code V' = V · M}, {@code M} the reflection in
 *       {@code y = level}, with Lengyel's oblique near plane in the water ({@link org.openworld.engine.water.MirrorCamera}),
 *       so nothing under the water is drawn or even sent (the culling uses the same frustum). The terrain's
 *       screen-error rule counts the reflection's own pixels, half resolution by default ({@code water.reflection}),
 *       so it is drawn coarser by itself (under {@code lod.rule=paper}: {@code lod.reflection-coarsening} levels).</li>
 *   <li>Refraction: the scene's colour and depth, copied just before the water is drawn: what lies behind the water
 *       is already in the picture, so no second pass is needed to see it.</li>
 *   <li>Mix: {@code F · reflection + (1 − F) · (T · behind + (1 − T) · body) + glitter}, {@code F} the Fresnel
 *       reflectance of the rippled surface ({@link org.openworld.engine.water.Fresnel}, tabulated, total internal
 *       reflection included), {@code T = exp(−σ d)} over the path {@code d} through the water to the ground and up
 *       from its depth, {@code σ} and the body colour from {@link org.openworld.engine.water.WaterOptics}.</li>
 *   <li>Ripples: a looping FFT ocean (Tessendorf 2001) of slopes ({@link org.openworld.engine.water.RippleField},
 *       its waves drawn from {@code engine.seed}), sampled at two unrelated scales; their slope variance is Cox and
 *       Munk's for the wind, the part the texture cannot resolve spreads the sun's glitter (a Beckmann lobe).
 *       Ripples bend where the reflection and the refraction are looked up.</li>
 *   <li>Where the bent reflected ray leaves the reflection picture, the sky's cube map answers.</li>
 *   <li>Under the water the reflection pass rests; every pixel is seen through {@code exp(−σ d)} of water glowing
 *       with its in-water colour, and the surface from below shows the world above through Snell's window and
 *       mirrors the water beyond it.</li>
 * </ul>
 *
 * <p><b>Cost.</b> The reflection pass redraws the terrain (a quarter of the pixels, a quarter of the triangles) and
 * the sky; the water itself is one full-screen pass of about 20 texture reads per pixel, plus a copy of the scene.
 * Start-up: the ripple field, 64 frames of 128² by FFT, about 0.2 s. Figures in {@code docs/benchmarks.md}.
 *
 * <p><b>Limits.</b> A plane, not a height field: no lakes above sea level, no waves that move the geometry, no
 * foam. The reflection is exact only for a flat surface; the ripples bend its look-up as if what they reflect were
 * far away. The pictures are mixed after tone mapping. The eye within 5 cm of the surface has no reflection pass.
 */
package org.openworld.engine.water;

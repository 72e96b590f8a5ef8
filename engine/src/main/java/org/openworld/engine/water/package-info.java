/**
 * Reflective, transparent water to the horizon (paper section 3.3, figure 13): the paper's stencil method, and the
 * cleaner two-picture method its section 5 proposes, made physical. Page: {@code docs/water.md}.
 *
 * <p><b>The plane.</b> The water is the plane {@code y = water.level}, found per pixel: a full-screen triangle whose
 * fragment shader intersects the view ray with the plane ({@code t = (level − eye.y) / dir.y}). It needs no mesh, so
 * it reaches the horizon in every direction and never shows an edge.
 *
 * <p><b>Shaded only where seen.</b> Above the water the triangle carries the plane's own depth: a projection maps
 * planes to planes, so the plane's NDC depth is affine in the screen position, {@code z = a·x + b·y + c}, the plane
 * {@code (0, 1, 0, −level)} taken through {@code (VP⁻¹)ᵀ} ({@link org.openworld.engine.water.PlaneOnScreen}). The
 * corners carry it, a clip distance cuts the triangle at the horizon, depth clamping keeps it beyond the far plane.
 * The shader neither discards nor writes depth, so the water under the terrain is never shaded. Above and under the
 * water are two programs ({@code fresnel.frag}, {@code underwater.frag}), picked on the CPU.
 *
 * <p><b>The paper's method</b> ({@code water.method=STENCIL}, {@code stencil.frag}): the stencil cleared to 0xFF at
 * the start of MAIN ({@code WaterSystem.beginPass}), 0 written by every opaque fragment, 0xFF again where the water
 * plane is nearest, with its alpha {@code water.alpha}; the scene drawn upside down into a second framebuffer; that
 * picture blended where the stencil is 0xFF: {@code colour = reflection · α + ground · (1 − α)} (figure 13).
 *
 * <p><b>The Fresnel method</b> (default, {@code water.method=FRESNEL}):
 * <ul>
 *   <li>Reflection: the viewer mirrored in the plane, {@code V' = V · M}, {@code M} the reflection in
 *       {@code y = level}, with Lengyel's oblique near plane in the water ({@link org.openworld.engine.water.MirrorCamera}),
 *       so nothing under the water is drawn or even sent (the culling uses the same frustum). The terrain's
 *       screen-error rule counts the reflection's own pixels, half resolution by default ({@code water.reflection}),
 *       so it is drawn coarser by itself (under {@code lod.rule=paper}: {@code lod.reflection-coarsening} levels),
 *       and only in the bounding rectangle of the screen below the horizon (a scissor set in {@code beginPass}; the
 *       pass is skipped with no water in sight): a mirrored ray points below the horizontal, so the water reads the
 *       reflection below the horizon line only.</li>
 *   <li>Refraction: the scene's colour and depth, copied just before the water is drawn: what lies behind the water
 *       is already in the picture, so no second pass is needed to see it.</li>
 *   <li>Mix: {@code F · reflection + (1 − F) · (T · behind + (1 − T) · body) + glitter}, {@code F} the Fresnel
 *       reflectance of the rippled surface ({@link org.openworld.engine.water.Fresnel}, tabulated, total internal
 *       reflection included), {@code T = exp(−σ d)} over the path {@code d} through the water to the ground and up
 *       from its depth, {@code σ} and the body colour from {@link org.openworld.engine.water.WaterOptics}.</li>
 *   <li>Ripples: a looping FFT ocean (Tessendorf 2001) of slopes ({@link org.openworld.engine.water.RippleField},
 *       its waves drawn from {@code engine.seed}), sampled at two unrelated scales, each layer holding two
 *       successive frames (RG and BA) so the blend between frames is one texture read; their slope variance is Cox
 *       and Munk's for the wind, the part the texture cannot resolve spreads the sun's glitter (a Beckmann lobe).
 *       Ripples bend where the reflection and the refraction are looked up.</li>
 *   <li>Two guards on the bent reflection ({@code fresnel.frag}): a look-up is kept only where the scene copy shows
 *       water or sky at its texel and one mirror texel above (else the plain mirror); and a ripple layer of tile
 *       {@code L} keeps the share {@code log2(L / (8 w)) / log2(size / 2)} of its slopes for a pixel footprint
 *       {@code w} on the water, the variance dropped widening the glitter's lobe.</li>
 *   <li>Where the bent reflected ray leaves the reflection picture, the sky's cube map answers.</li>
 *   <li>Under the water the reflection pass rests; every pixel is seen through {@code exp(−σ d)} of water glowing
 *       with its in-water colour, and the surface from below shows the world above through Snell's window and
 *       mirrors the water beyond it.</li>
 * </ul>
 *
 * <p><b>Cost.</b> The reflection pass redraws the terrain (a quarter of the pixels, a quarter of the triangles) and
 * the sky, below the horizon; the water shades only the pixels where it is seen, about 11 texture reads each, plus a
 * copy of the scene; at start-up the ripple field, 64 frames of 128² by FFT. Measured in docs/water.md, "Cost".
 *
 * <p><b>Files.</b> {@link org.openworld.engine.water.WaterSystem} (the passes), {@code WaterPrograms} (the
 * programs); {@code shaders/water/}: {@code water.vert}, {@code surface.glsl} (the plane per pixel),
 * {@code optics.glsl} (what both programs share: ripples, Fresnel table, light in the water), the fragment programs.
 * <b>Limits.</b> A plane, not a height field: no lakes above sea level, no waves that move the geometry, no foam;
 * the reflection is exact only for a flat surface. The page has them all ("Limits") and why the guards are there.
 */
package org.openworld.engine.water;

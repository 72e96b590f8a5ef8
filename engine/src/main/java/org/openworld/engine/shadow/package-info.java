/**
 * The sun's shadows: shadow mapping (paper section 3.2, figures 10–12) and, as the default, stable cascaded shadow
 * maps, which fix the paper's own flaw, shadows that alias and flicker as the world grows. Page: {@code docs/shadows.md}.
 *
 * <h2>Shadow mapping</h2>
 * An orthographic camera looks along the sunlight and records, per texel, the depth of the nearest surface: the
 * {@link org.openworld.engine.core.Pass#SHADOW} pass, owned by {@link org.openworld.engine.shadow.ShadowSystem} and
 * drawn by the casters (the terrain, depth only). A lit shader then asks, for its point p, with the map's
 * transform M (world to the map's clip space) and {@code shaders/common/shadow.glsl}:
 * <pre>
 *   (u, v, z) = ½ · M · p + ½          the point's texel and depth in the sun's picture
 *   lit       = z − bias ≤ map(u, v)    nothing nearer the sun there
 * </pre>
 * The paper's two fixes, both settings: the <b>margin</b> (its bias, in depth-buffer units: figure 10's 0, 0.001,
 * 0.01, 0.1), against the surface shadowing itself where one texel's single depth stands for a tilted patch of
 * ground ("acne"), at the price of shadows that come loose from their casters when too large; and
 * <b>percentage-closer filtering</b> (figure 11's 1×1 to 7×7 kernels): the mean of N × N such tests a texel apart,
 * a soft edge N texels wide instead of a jagged one. Beyond the paper, the sun's disc (0.53°) blurs an edge by
 * 0.93 cm per metre between caster and ground: with {@code shadow.penumbra} one more test, against a depth
 * {@code 1.5 N t / 0.0093} metres nearer the sun (t the texel), finds casters far enough for that blur to outgrow the
 * filter, and there the N × N tests spread to two texels apart.
 *
 * <h2>Cascades, the default</h2>
 * One map over an 8 km view has 4 m texels, and refitted every frame ({@link
 * org.openworld.engine.shadow.LightFit#covering}) its grid slides over the world and every edge shimmers. The default
 * ({@link org.openworld.engine.shadow.ShadowSettings.Method#CASCADES}):
 * <ul>
 *   <li><b>Cascades</b> ({@link org.openworld.engine.shadow.CascadeSplits}): the view is cut at distances
 *       {@code d_i = λ·n·(f/n)^(i/c) + (1−λ)·(n + (f−n)·i/c)} (Zhang et al. 2006), one map per slice.</li>
 *   <li><b>Stable fit</b> ({@link org.openworld.engine.shadow.LightFit#stable}): a square around the slice's bounding
 *       sphere (its size set by the slice alone), its centre moved by whole texels, so the grid stays fixed in the
 *       world; one spare texel a side leaves room for the snap.</li>
 *   <li><b>Biases that follow the geometry</b>: a slope bias of {@code texel · tan θ} towards the sun times the
 *       filter's reach, a normal offset of {@code texel · sin θ} (θ the sun's angle to the normal), per cascade.</li>
 *   <li><b>Blending</b>: the next map over each map's outer tenth; a fade over the last tenth of
 *       {@code shadow.distance}.</li>
 * </ul>
 * Each box reaches towards the sun as far as a caster can stand (the height span the culling system knows of, over
 * the sine of the sun's elevation); the culling system culls the casters against each box, and the terrain draws
 * them at the viewer's levels ({@code lod.rule=paper}: {@code lod.shadow-coarsening} levels coarser).
 * {@link org.openworld.engine.shadow.CascadeRefresh} keeps a map whose fitted box and casters are unchanged
 * ({@code shadow.refresh}) until the sun turns by {@code shadow.refresh-angle}; staggered, cascade i waits for its
 * turn, at most every 2^i frames.
 *
 * <h2>The data path and the lookup</h2>
 * {@link org.openworld.engine.shadow.ShadowSystem} fits the boxes, asks the engine for one depth-only view per map to
 * redraw (a layer of a depth texture array) and publishes the maps with the uniform block that says how to read them
 * as the world's {@code SunShadow}, which every lit shader reads.
 * {@code sunVisibility} ({@code shaders/common/shadow.glsl}) walks the cascades from the finest and filters in the
 * first that holds the point; inside its blend band the loop's next trip filters the next cascade and blends the two.
 * With {@code shadow.measure} on, {@link org.openworld.engine.shadow.ShadowProbe} counts the picture's flicker and acne.
 *
 * <p><b>Cost and limits.</b> Per frame one depth-only pass per map redrawn (the terrain's vertex work again) and per
 * lit pixel N² + 1 depth tests, twice that in a blend band; the clouds cast no shadows, a kept map lags the casters
 * that change with the viewer, the margin means different metres for different boxes. The page
 * {@code docs/shadows.md} has the measurements ("Measures", "Cost"), the lookups tried and the limits in full.
 */
package org.openworld.engine.shadow;

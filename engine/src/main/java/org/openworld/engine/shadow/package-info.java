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
 * <h2>Why the paper's map fails on a big world, and cascades</h2>
 * One map over everything the camera sees spreads its texels over kilometres: 2048 texels over an 8 km view are 4 m
 * each, so near shadows are blocks. And refitted to the view every frame ({@link
 * org.openworld.engine.shadow.LightFit#covering}), the map's texel grid slides over the world by fractions of a texel
 * as the camera moves or turns, and every shadow edge shimmers. The default
 * ({@link org.openworld.engine.shadow.ShadowSettings.Method#CASCADES}):
 * <ul>
 *   <li><b>Cascades</b> ({@link org.openworld.engine.shadow.CascadeSplits}): the view is cut at distances
 *       {@code d_i = λ·n·(f/n)^(i/c) + (1−λ)·(n + (f−n)·i/c)} (Zhang et al. 2006), and each slice gets its own map, so
 *       texels near the eye are small and far ones large, roughly in step with the pixels they fall under.</li>
 *   <li><b>Stable fit</b> ({@link org.openworld.engine.shadow.LightFit#stable}): each map is a square around the
 *       slice's bounding sphere, whose radius depends on the slice alone, never on where the camera turns; its centre
 *       is moved to a whole number of texels, so the texel grid stays fixed in the world and edges do not swim. One
 *       spare texel on each side leaves room for the snap. The box's position lives in its projection, and its view
 *       is the sun's rotation alone, so the snapped translation is held exactly in floats.</li>
 *   <li><b>Biases that follow the geometry</b>: the slope bias pulls the compared depth towards the sun by
 *       {@code texel · tan θ} (θ the sun's angle to the normal: how much depth one texel of tilted ground spans), times
 *       the filter's reach; the normal offset moves the looked-up point {@code texel · sin θ} off the surface. Both
 *       scale with each cascade's texel, where the paper's margin is one number for all.</li>
 *   <li><b>Blending</b>: over the outer tenth of a map the next one is mixed in, and over the last tenth of
 *       {@code shadow.distance} shadows fade out, so no seam shows.</li>
 * </ul>
 * Every box reaches towards the sun beyond its slice as far as a caster can stand: the height span of everything the
 * culling system knows of, over the sine of the sun's elevation. Each box is a pass camera like any other, so the
 * culling system culls the casters against it, and the terrain draws them at the levels the viewer sees them at
 * (the viewer's cut, so no caster stands above or below the ground that receives its shadow; under
 * {@code lod.rule=paper}: levels from the viewer's eye, {@code lod.shadow-coarsening} levels coarser).
 *
 * <h2>Redrawing only what moved</h2>
 * The stable fit moves a box by whole texels only, so while the fitted box is the one a map was drawn with and the
 * casters are unchanged, a redraw would write the same depths: {@link org.openworld.engine.shadow.CascadeRefresh}
 * keeps such a map ({@code shadow.refresh}, the engine gets no view for it), until the sun has turned by more than
 * {@code shadow.refresh-angle}; staggered (the default), far cascade i waits for its turn, at most every 2^i frames.
 *
 * <h2>The lookup</h2>
 * {@code sunVisibility} ({@code shaders/common/shadow.glsl}) walks the cascades from the finest and filters in the
 * first that holds the point; inside its blend band the loop's next trip filters the next cascade and blends the two.
 *
 * <h2>Cost and limits</h2>
 * Per frame: one depth-only pass per cascade that moved (the terrain's vertex work again, at a coarser level), and
 * per lit pixel N² + 1 depth tests, twice that in a blend band; measured in {@code docs/shadows.md}, "Cost". Limits: a kept map lags the casters that change with the viewer (the terrain's levels, the
 * trees' fade) by the frames it waits; the clouds cast no shadows; the penumbra widens an edge by at most twice the
 * filter, into the shadow only; the sphere
 * fit wastes texels on a wide view; a sun within 8° of the zenith turns the maps' "up" to north, so the texel grid
 * turns once when the sun crosses that line; the margin, in depth units, means different metres for different boxes,
 * as it did in the paper.
 *
 * <p>With {@code shadow.measure} on, {@link org.openworld.engine.shadow.ShadowProbe} counts the flicker and the acne
 * of the picture (docs/shadows.md, "Measures").
 */
package org.openworld.engine.shadow;

/**
 * Far from the origin: camera-relative rendering with a floating render origin. The CPU holds world positions in
 * double; the GPU gets them from a {@link org.openworld.engine.origin.RenderOrigin} near the viewer, so a float,
 * whose 24 bits are 1 m apart at 10 000 km, never holds more than the few kilometres between a point and the eye.
 *
 * <h2>The data path</h2>
 * <ol>
 *   <li>Before each frame's passes the engine moves the origin o to the viewer's x and z rounded to a multiple of
 *       the step: the terrain's tile (a root's side of the unbounded world), 4096 m by default; y stays 0.</li>
 *   <li>Every view the GPU takes is {@code V · T(o)}, multiplied in double from the camera's double view
 *       ({@code ViewCamera#viewFrom}); so are the sun's shadow matrices ({@code L · T(o)}); the eyes in the frame and
 *       shadow blocks are {@code eye − o}. The frame block also holds o as a whole number of steps
 *       ({@code shaders/common/frame.glsl}'s origin).</li>
 *   <li>Per-instance positions are written from o: the terrain's copies ({@code copyOffset − o}), the trees' feet
 *       (from their placement's centre, itself given from o), the far field's square.</li>
 *   <li>What a shader reads by world position gets o's share reduced in double, modulo its own period: the tile's
 *       maps repeat every step, so they need nothing; the streamed clipmap adds o's samples in int
 *       ({@code shaders/terrain/stream/clipmap.glsl}); the materials' noise lattices and tiles take o's coordinates on
 *       each, split into a whole part modulo the hash's period and a fraction ({@link
 *       org.openworld.engine.origin.MaterialOrigin}: {@code c = floor(p + f) + w} is the world's cell exactly);
 *       the water's two ripple layers take o modulo their tiles.</li>
 * </ol>
 * Since o moves in whole steps and every offset moves with it, nothing on the screen moves when it does.
 *
 * <h2>Cost</h2>
 * Per frame a few dozen double multiplications on the CPU and, per material bind, 14 vec4 uniforms; per pixel of
 * the materials an add per lattice. Within the measurement's noise (docs/benchmarks.md).
 *
 * <h2>Limits</h2>
 * The camera stays within 2^24 m of the world's origin ({@code CameraPose.MAX_COORDINATE_M}): the level of detail's
 * eye, the culling's boxes and the light boxes' fit are still computed in float from world coordinates, 1 m
 * apart from 2^24 m on. The stochastic tiling's skewed lattice takes o's whole tiles reduced modulo the hash's
 * period through a float product, so its triangles may shift when o crosses 27 km of whole tiles (the default
 * tiling repeats and has no lattice). The snow's flakes are simulated in world coordinates in float
 * (org.openworld.engine.particles), centimetres off at 10 000 km.
 */
package org.openworld.engine.origin;

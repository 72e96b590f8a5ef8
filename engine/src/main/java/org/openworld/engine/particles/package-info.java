/**
 * Snowfall (paper section 4, figure 14): particles updated on the GPU by transform feedback and drawn as instanced
 * billboards. Page: {@code docs/particles.md}.
 *
 * <p><b>Update</b> ({@code shaders/particles/update.vert}, its CPU twin {@link org.openworld.engine.particles.SnowMotion}).
 * Each flake is six floats, position and velocity, in one of two buffers. Each simulation step draws the flakes as
 * points from one buffer with the rasteriser off; the vertex shader's outputs are captured into the other buffer,
 * and the two swap. Per step dt (semi-implicit Euler):
 * <pre>
 *   v ← v + dt · (−g ŷ + k (w − v)) + σ √dt ξ        p ← p + dt · v
 * </pre>
 * gravity g, drag k towards the wind w (the clouds' {@link org.openworld.engine.environment.Wind}, times
 * {@code particles.wind-share}), and the paper's random acceleration: ξ three standard normal numbers drawn anew each
 * step from a hash of the flake's index and the step (seeded, the same on the CPU). In still air a flake settles at
 * the terminal velocity g / k, which is {@code particles.fall-speed} (so g = k · fall speed); the random term makes
 * each velocity component an Ornstein–Uhlenbeck process whose spread settles at σ / √(2k), which is
 * {@code particles.turbulence}.
 *
 * <p><b>Where the snow is.</b> The flakes fill a cube of side L ({@code particles.volume}) around the eye: a flake
 * leaving it through a face comes back through the opposite one (through a side face at the same height above the
 * ground), so the eye never reaches the snow's edge. A flake below the ground, looked up in a
 * {@link org.openworld.engine.particles.GroundPatch} sampled from the world's height field, starts again at the
 * cube's top. A fresh fall is spread through the cube's air when it starts to snow, when the count changes (new
 * buffers, once) and when the eye jumps.
 *
 * <p><b>Drawing</b> ({@code shaders/particles/flake.vert}, {@code flake.frag}): one instance per flake of a square
 * {@code Mesh} (four corners, two triangles) facing the camera, one {@code Mesh.drawInstances} call for them all. The fragment shader keeps the disc within the square, its
 * opacity falling off over the outer 60% of the radius. A flake narrower than a pixel is drawn a pixel wide with its
 * opacity times (true radius / drawn radius)², the light it would cover; flakes fade out towards the cube's
 * inscribed sphere, so none pops in as it wraps; and where the volumetric clouds are, with the share of the snowfall
 * that falls under the cloud overhead ({@code snowfallShare}, {@code common/shadow.glsl}: the column's optical depth
 * over 3, at most 1; none under a clear sky). Lit as a thin translucent plate at a random angle: albedo ·
 * (½ · sun · visibility + sky), the sun's visibility from the shadow maps, then the air's fog. Premultiplied alpha,
 * blended over the picture after every opaque system ({@code SystemSpec.layer(Layer.TRANSPARENT)}), without sorting: all
 * flakes are one colour, so the order barely shows.
 *
 * <p><b>Cost.</b> The update reads and writes 24 bytes per flake per step; the draw is 4 vertices and 2 triangles
 * per flake, most of them dropped in the vertex shader (behind the eye, beside the view, faded), and a few pixels
 * for each one kept. Memory: 48 bytes per flake (two buffers), 48 MB for a million. Measured: update span
 * {@code update.particles} and draw span {@code main.particles} in {@code openworld bench}; figures in
 * {@code docs/benchmarks.md}.
 *
 * <p><b>Limits.</b> Flakes are discs, not crystals, and have no motion blur. They neither cast shadows nor settle on
 * the ground, and the reflection pass does not draw them. The random term pushes each flake alone: there are no
 * gusts or eddies that move neighbours together. Flakes under the water live on until they reach the sea bed.
 * Unsorted blending is exact only for flakes of one colour.
 */
package org.openworld.engine.particles;

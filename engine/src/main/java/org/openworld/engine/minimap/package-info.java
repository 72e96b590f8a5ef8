/**
 * A minimap: a small top-down map of the ground around the camera in a corner of the picture, north up, with a
 * marker at the camera pointing where it looks. It is the example system of {@code docs/adding-a-system.md}, which
 * builds it step by step; one line in the demo's scene adds it.
 *
 * <p><b>The map</b> ({@link org.openworld.engine.minimap.ReliefMap}). The world's
 * {@link org.openworld.engine.core.HeightField} is sampled on the CPU on a 512 × 512 grid around the camera, 1.5
 * times the range shown across: the range, plus a quarter of it on each side, so the camera can move a quarter of
 * the range before the map is built again. Each sample is shaded by its slope (a hillshade): with the ground's normal
 * n = (−∂h/∂x, 1, −∂h/∂z) / |…| from central differences and a fixed light l from the north-west, 45° up (the
 * cartographers' light: from the top of a north-up map, hills read as hills),
 * <pre>
 *   colour = land · (a + (1 − a) · max(0, n · l))      a = 0.3, the light on slopes turned away
 * </pre>
 * and ground below the world's {@link org.openworld.engine.environment.WaterLevel} (which the water system writes
 * from {@code water.level}) is a flat blue (no water level in the world: no water). The colours go into an RGBA8
 * texture as display (sRGB) values. The grid is snapped to its own spacing, so a map built again samples the same
 * points and the picture does not swim.
 *
 * <p><b>Drawing</b> ({@code shaders/minimap/minimap.vert}, {@code minimap.frag}), in the
 * {@link org.openworld.engine.core.Pass#OVERLAY} pass, after every other system drawing there: one square of two
 * triangles, placed in pixels from the frame block's viewport. The fragment shader looks the texture up at the
 * camera's exact position plus its offset on the map, so the map slides smoothly between rebuilds; it draws the
 * marker, a dart turned to the camera's yaw, from its signed distance (red, with a white rim and a pixel of
 * anti-aliasing), and a 2-pixel border. No depth test, no depth written, no blending.
 *
 * <p><b>Cost.</b> Per frame one draw call and a texture fetch per covered pixel: 0.2 ms GPU (median,
 * {@code overlay.minimap}) and under 0.1 ms CPU at 1280 × 720 on llvmpipe. A rebuild samples 514² heights and shades
 * 512² texels on the render thread: 6–7 ms with the JIT warm (50 ms the first time), once per quarter of the range
 * flown (1 km at the default 4 km range) and on a change of range or water level; the upload is 1 MB. GPU memory:
 * one 512² RGBA8 texture, 1 MB.
 *
 * <p><b>Limits.</b> The map shows only the height field: no snow, no materials, no other entities. The shading's
 * light is fixed, not the sun's. A rebuild is a one-frame hitch on the render thread (a worker thread would hide
 * it, CONTRIBUTING.md, "Threads"). The range is square and north is always up; the map does not rotate with the camera. Between
 * samples the texture blends colours bilinearly, so a coast is as sharp as one sample, 12 m at the default range.
 */
package org.openworld.engine.minimap;

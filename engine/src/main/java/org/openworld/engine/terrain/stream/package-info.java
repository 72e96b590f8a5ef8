/**
 * The terrain's fifth stage, for the unbounded world: heights streamed around the camera. In: the octave bands
 * ({@link org.openworld.engine.terrain.heights.BandedHeights}) and the camera's pose and velocity. Out: a clipmap of
 * levels on the GPU ({@link org.openworld.engine.terrain.stream.HeightClipmap}) with their slopes, snow and sky
 * occlusion made per block, and which quadtree nodes are resident
 * ({@link org.openworld.engine.terrain.lod.Residency}) for the level-of-detail stage's cut.
 *
 * <p><b>Drawing the unbounded world ({@code terrain.world=unbounded}).</b> A clipmap ({@link
 * org.openworld.engine.terrain.stream.HeightClipmap}) keeps each level in an S × S window around the camera, world sample i
 * of level L in texel {@code i mod S} of layer L (toroidal: a moving window rewrites only the blocks that enter it),
 * made on worker threads ahead of the camera by its velocity and uploaded a few blocks a frame. The quadtree's roots
 * (8 km) lie on a lattice around the camera as the tile's copies do, each a different piece of the world; a node is
 * split only into children whose levels are resident ({@link org.openworld.engine.terrain.lod.Residency}), so a block
 * not made yet shows as coarser ground, never a hole ({@link org.openworld.engine.terrain.stream.StreamedWorld}). Cost:
 * {@code 10 · levels · S²} bytes of GPU memory (heights, slopes, snow), 20 MiB by default whatever the distance
 * flown; a 64² block takes 0.57–1.95 ms of a worker. Its snow ({@link org.openworld.engine.terrain.stream.StreamedSnow}) is
 * the tile's, made over each block with its border, so blocks join without seams; coarser levels show its mean.
 * Its sky occlusion ({@link org.openworld.engine.terrain.stream.StreamedSky}) is the tile's V
 * ({@link org.openworld.engine.terrain.material.HorizonSearch}), the same search run for each block by a fragment
 * pass that marches the clipmap's own levels once the heights it reads have arrived (a
 * table of which block each slot holds keeps it off stale texels; beyond a window it falls back on a coarser level):
 * on llvmpipe several milliseconds a block, so the start shades only the blocks its first frame draws, and the blocks
 * no pass draws yet wait for a budget of one level-0 block's pass a frame ({@link
 * org.openworld.engine.terrain.stream.FrameBudget}): a burst of arrivals never stalls the frame it arrives in. Limits: one
 * geometric error per level (the world is statistically uniform), boxes the world's height bounds where no blocks
 * narrow them; no baked far material: its far program samples the coarse tile alone ({@link
 * org.openworld.engine.terrain.TerrainShading}).
 */
package org.openworld.engine.terrain.stream;

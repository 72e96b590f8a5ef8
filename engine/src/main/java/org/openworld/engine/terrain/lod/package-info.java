/**
 * The terrain's second stage: level of detail. In: the quadtree's bounds and geometric errors over the heights
 * ({@link org.openworld.engine.terrain.lod.TerrainQuadtree}), the camera and a rule. Out: the cut, a
 * {@link org.openworld.engine.terrain.lod.PatchList} of patches, each with its level, the levels of its four sides
 * and corners (for stitching) and its geomorph factor. The quadtree cut ({@code lod.mode=quadtree}) and the paper's
 * flat grid ({@code lod.mode=flat-grid}) are the two schemes ({@link org.openworld.engine.terrain.lod.LodScheme}).
 *
 * <p><b>Level of detail (2.5).</b> Every patch is the same grid of N × N cells (N = 32 or 64). A quadtree node of
 * level L covers 2^L leaf patches and reads pyramid level L; the cut splits a node while it is not fine enough
 * ({@link org.openworld.engine.terrain.lod.QuadtreeLod}), with D the distance from the camera to the node's box (not its
 * centroid: a big node around the camera would otherwise be drawn coarse). Two rules say when a node is fine enough
 * ({@link org.openworld.engine.terrain.lod.LodRule}, made per pass into a {@link org.openworld.engine.terrain.lod.DetailLimit}):
 * <ul>
 *   <li>the screen error, the default: each node's geometric error e, the largest |surface of its level − finest
 *       height| over its samples ({@link org.openworld.engine.terrain.lod.GeometricError}, computed once from the
 *       pyramid), may cover at most {@code lod.pixel-error} pixels: {@code e · (H/2) / (tan(fov/2) · D) ≤ p} for a
 *       target H pixels high. Triangles go where the relief shows: flat ground stays coarse near the eye, ridges stay
 *       fine far off. The sun's orthographic pass has no distance of its own: it cuts its casters from the viewer's
 *       eye by the viewer's own limit, so that they are the very ground that receives their shadows (a caster finer
 *       than that ground shadows it under every bump it keeps; one coarser stands above it in every hollow and
 *       shadows it there: the specks of the paper rule's {@code lod.shadow-coarsening}, the dark streaks of acne
 *       down a sunlit face).
 *       Cost: one pass over the samples per level when the world is built (about 0.2 s for 2048², with the boxes),
 *       one comparison per visited node per frame;</li>
 *   <li>the paper's {@code L_B(D) = ⌊log2(D/B)⌋} ({@link org.openworld.engine.terrain.lod.LodRule#level}): a node is split
 *       while its level exceeds {@code L_B(D)}, whatever the relief. The drawn ring of each level then has a fixed
 *       number of patches, so the count grows with the logarithm of the world's size (the paper's equation 1):
 *       measured 22, 34, 46, 58 patches for worlds of 256² to 2048².</li>
 * </ul>
 * The paper's own flat grid of patches, each with its own level (by centroid distance under its rule), stays as
 * {@code lod.mode=flat-grid} with {@code lod.rule=paper} for figure 6; its cost grows with the area. Limits of the
 * bound: it holds at the samples, for a patch's own level; a side stitched to a coarser neighbour reads that
 * neighbour's level, whose own bound covers the side, and the strip between blends the two.
 *
 * <p><b>The scheme and the source.</b> The scheme ({@code lod.mode}) is chosen apart from the height source: both
 * schemes cut the quadtree that any source's heights give ({@link org.openworld.engine.terrain.lod.TerrainQuadtree}),
 * and ask a {@link org.openworld.engine.terrain.lod.Residency} which nodes they may draw, so how the levels reach
 * the GPU (a tile's mips, the unbounded world's streamed clipmap) is the ground's, not the scheme's. The one
 * property of the source a scheme needs is {@link org.openworld.engine.terrain.lod.Residency#whole}: the flat grid
 * puts every leaf of every copy in its cut, so it runs only where every node is there from the start; over
 * streamed levels (each root a tile's worth of leaves, most of them not yet there) the quadtree's cut stands in
 * ({@link org.openworld.engine.terrain.lod.PatchSelection}).
 *
 * <p><b>Geomorphing (CDLOD-style after Strugar 2009).</b> In the quadtree cut each patch morphs into its
 * parent's surface before it merges: it carries a factor k that rises from 0 to 1, by its box's distance D, over the
 * last 30 % of the way from its own merge distance to its parent's ({@link org.openworld.engine.terrain.lod.DetailLimit#fineFrom}:
 * B · 2^L under the paper's rule, e · f / p under the screen error), and the vertex shader blends each vertex's
 * height towards the coarser level's surface by k. A node splits where its k is 0 and its children appear with
 * k = 1, on the same surface, so the switch moves nothing; shared edge and corner vertices take the largest k of the
 * patches sampling their level, so neighbours agree ({@link org.openworld.engine.terrain.lod.QuadtreeLod} has the
 * argument). Cost: two more height fetches per morphing vertex and 36 bytes per instance. On by default
 * ({@code lod.morph}); the flat grid (figure 6) never morphs.
 */
package org.openworld.engine.terrain.lod;

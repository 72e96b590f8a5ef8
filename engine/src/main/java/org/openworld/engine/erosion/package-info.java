/**
 * Erosion of the tile and of the unbounded world ({@code terrain.erosion}): heights carved by rivers and settled to their talus, so that the
 * land measures like a real one ({@link org.openworld.engine.drainage}; {@code docs/terrain.md}, section 6).
 *
 * <p><b>Stream power with uplift</b> ({@link org.openworld.engine.erosion.StreamPower}). Rivers cut at the rate
 * {@code K A^m S^n}; where uplift U balances it the land is in steady state, {@code S = (U/K)^{1/n} A^{−m/n}}, Flint's
 * law with θ = m/n (Cordonnier, Braun, Cani, Benes, Galin, Peytavie and Guérin 2016, "Large Scale Terrain Generation
 * from Tectonic Uplift and Fluvial Erosion"). With n = 1 the steady state follows from the outlets up in one pass
 * over the flow network in its stack order (Braun and Willett 2013's implicit scheme at an infinite time step):
 * {@code z_c = z_receiver + min(k_s A^−θ, tan talus) · d}. O(n) after the routing.
 *
 * <p><b>The tile</b> ({@link org.openworld.engine.erosion.TileErosion}), between synthesis and pyramid: on the level
 * 8 m apart, k_s ∝ 0.05 + 0.95 √(h / h_max) (ranges where the spectrum put its highs), the sea as base level; eight
 * rounds of routing ({@link org.openworld.engine.drainage.FlowNetwork}, periodic) and rebuilding, k_s scaled each
 * round so the highest peak keeps its height; then thermal relaxation
 * ({@link org.openworld.engine.erosion.Thermal}, Musgrave, Kolb and Mace 1989: an eighth of each side's excess over
 * the talus slides per pass, 24 Jacobi passes, volume kept); then level 0 = the carved level read bilinearly +
 * (base − its own coarse level) · 1 / (1 + A / 10⁴ m²), the spectrum's finer detail, smoothed away in river beds.
 * Periodic in, periodic out; the same map gives the same bits.
 *
 * <p><b>The unbounded world</b> ({@link org.openworld.engine.erosion.ErodedWorld}). Flow is not local: a river's
 * height at a place depends on everything upstream and on its way to the sea, and the world has no edge to route
 * from. The plan: erode every level from the routing level (8 m) up to the coarsest band (512 m) on its own fixed
 * lattice of regions, coarse levels first, each level taking the coarser one's rivers as given.
 * <ul>
 * <li><b>Regions, independent of the blocks.</b> Level L's regions are cores of 128² samples on a lattice from
 * sample 0, each routed with 16 samples of overlap and a 32-sample apron beyond (225² samples,
 * {@link org.openworld.engine.erosion.RegionErosion}): the steady state above, the region's border and the sea as
 * base level, k_s = 150 m · (0.05 + 0.95 √(h / relief)) from the plain height h, two rounds, the thermal step.
 * A sample's displacement is the regions' displacements weighted by a partition of unity, 1 inside a core and
 * ramping linearly across the 32 samples about a line between cores
 * ({@link org.openworld.engine.erosion.ErodedWorld#weights}): no seam where two regions' networks differ, and a
 * height is a pure function of level, place and seed. Blocks made in any order, on any thread, agree to the bit.</li>
 * <li><b>Coarse to fine (the cascade).</b> A region of level L starts from its bands plus level L + 1's
 * displacement, read bilinearly, and every cell on one of its own channels (8 cells or more) that lies along a
 * river of level L + 1 (4 096 of that level's cells or more) takes that river's drainage area into the law: so
 * the big rivers, routed where regions are tens of kilometres across, keep their gentle profiles on the fine
 * levels, whose regions are 1 km across, and each level routes only the valleys of its own scale. Without the
 * cascade each level's rivers would start at its regions' borders, the levels would disagree by hundreds of
 * metres, and no region of the fine levels would be large enough for a river of 10 km².</li>
 * <li><b>Below the routing level</b> the displacement of the routing level is read bilinearly under the finer
 * bands. Every height is clamped to the plain world's bounds, which the level choice's boxes use.</li>
 * <li><b>Levels' errors.</b> The plain bands' errors plus the largest difference, at 4 000 places near the origin,
 * between the displacement level 0 carries and the one level L's triangles draw: by the triangle inequality the
 * eroded surface lies within the sum.</li>
 * </ul>
 * Why not the tile's way on the coarse bands: their sum is not periodic (each band turns by its own angle), and a
 * big periodic tile under a non-periodic world would make it repeat. Why not erode each streamed block with an
 * apron: then a block's heights would depend on which blocks exist, and two blocks would disagree at their seam
 * unless their aprons reached every river's outlet.
 *
 * <p><b>Why this scheme.</b> The steady state gives Flint's law by construction and costs a few routings, where a
 * time-stepped shallow-water simulation (Mei, Decaudin and Hu 2007) needs thousands of steps to organise a network
 * at this scale and gives no guaranteed θ. It is detachment-limited: eroded material leaves through the sea, none is
 * deposited.
 *
 * <p><b>Then sediment.</b> On the tile {@code TerrainData} runs the hydraulic and thermal erosion of
 * {@link org.openworld.engine.erosion.hydraulic} on the carved 8 m level (on the GPU at start, on the CPU in the
 * {@code heightmap} command): the slopes' sheet wash laid in the valley floors, the faces above the talus slid to
 * their feet.
 *
 * <p><b>Cost.</b> The tile: 4.7–7.2 s for the default 2048² tile at start (eight routings of 512², each a
 * priority-flood), on the shared two-core machine; nothing per frame. Memory: a few arrays of the 512² level.
 * The unbounded world: a region is two routings of 225² (docs/terrain.md has the figures per block and at
 * start), made on the streaming's worker threads as the blocks that need them are made; 49 regions a level are
 * kept (203 KiB each: displacement and area over 161² samples), 9.7 MiB a level, 68 MiB for the 7 levels eroded.
 *
 * <p><b>Limits.</b> The stream power runs on the CPU. The tile's Hack exponent stays at 0.45 (a single level
 * routed; the unbounded world's cascade gives 0.61); hillslopes at the talus are planar faces between 8 m samples;
 * the unbounded world gets no sediment (the hydraulic step runs on the tile only). On the unbounded world the ramp
 * between regions can leave a valley that one region carved and its neighbour did not fading out over 32 samples.
 */
package org.openworld.engine.erosion;

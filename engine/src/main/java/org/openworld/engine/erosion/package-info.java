/**
 * Erosion of the tile ({@code terrain.erosion}): heights carved by rivers and settled to their talus, so that the
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
 * <p><b>Why this scheme.</b> The steady state gives Flint's law by construction and costs a few routings, where a
 * time-stepped shallow-water simulation (Mei, Decaudin and Hu 2007) needs thousands of steps to organise a network
 * at this scale and gives no guaranteed θ. It is detachment-limited: eroded material leaves through the sea, none is
 * deposited.
 *
 * <p><b>Then sediment.</b> {@code TerrainData} runs the hydraulic and thermal erosion of
 * {@link org.openworld.engine.erosion.hydraulic} on the carved 8 m level (on the GPU at start, on the CPU in the
 * {@code heightmap} command): the slopes' sheet wash laid in the valley floors, the faces above the talus slid to
 * their feet.
 *
 * <p><b>Cost.</b> 4.7–7.2 s for the default 2048² tile at start (eight routings of 512², each a priority-flood),
 * on the shared two-core machine; nothing per frame. Memory: a few arrays of the 512² level.
 *
 * <p><b>Limits.</b> CPU only and the tile only (the unbounded world is not eroded); Hack's exponent stays at
 * 0.45; hillslopes at the talus are planar faces between 8 m samples; this step lays no sediment (the hydraulic
 * step does).
 */
package org.openworld.engine.erosion;

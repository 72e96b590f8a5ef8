/**
 * Hydraulic and thermal erosion by virtual pipes, on the GPU: rain runs down the relief as a shallow sheet of water,
 * picks up sediment where it runs fast and steep, lays it down where it slows, and every slope steeper than the
 * talus slides (Mei, Decaudin and Hu 2007, "Fast Hydraulic Erosion Simulation and Visualization on GPU"; thermal
 * erosion after Musgrave, Kolb and Mace 1989). It runs after the stream-power step on the tile
 * ({@link org.openworld.engine.erosion.TileErosion}): the rivers have their valleys, and this step fills the valley
 * floors with what the slopes above them lose.
 *
 * <p><b>The state</b>, per cell of side l: terrain height b, water depth d, suspended sediment s (metres of material),
 * and the outflow f through the four pipes to the neighbours (m³/s). <b>One step</b> of Δt, four stages
 * in three passes ({@code shaders/erosion/}, each a full-screen triangle reading one texture and writing the other):
 * <ol>
 *   <li>{@code flux.frag}: rain, {@code d₁ = d + Δt r}; each pipe's flux accelerated by the drop of the water's
 *       surface, {@code f ← max(0, f + Δt · l² · g · Δh / l)}, and the four scaled by
 *       {@code K = min(1, d₁ l² / (Σf Δt))} so a cell never loses more water than it holds;</li>
 *   <li>{@code water.frag}: {@code d₂ = d₁ + Δt (Σf_in − Σf_out) / l²}; the velocity from the net flow through the
 *       cell's faces, {@code u = ½ (f_R(x−1) − f_L(x) + f_R(x) − f_L(x+1)) / (l d̄)}; the carrying capacity
 *       {@code C = K_c · sin α · |v| · min(d₂, d_cap)}; below it the bed gives {@code K_s (C − s)} to the load, above it the load
 *       lays {@code K_d (s − C)} on the bed;</li>
 *   <li>{@code transport.frag}: the load moves with the water, and the water evaporates,
 *       {@code d ← d₂ (1 − K_e Δt)};</li>
 *   <li>in the same pass (the transport does not change the bed the slide reads): an eighth of each side's drop in excess of {@code tan(talus) · l} slides down.</li>
 * </ol>
 * When the run stops, the suspended load is laid down where it is. {@link org.openworld.engine.erosion.hydraulic.PipeModel}
 * holds the constants and says their units.
 *
 * <p><b>Where it departs from the paper.</b> The capacity has the depth as a factor: the paper's
 * {@code K_c sin α |v|} lets a film of rain a few millimetres deep carry tens of centimetres of sediment, because the
 * pipes have no friction and the sheet runs at the scheme's limit of one cell a step; with the depth, the load grows
 * with the discharge per metre of width, as in stream-power transport laws, up to a depth d_cap (10 cm) past which
 * deeper water carries no more (without friction a deep river would otherwise cut without end). The paper moves the load
 * semi-Lagrangianly, {@code s(x) ← s(x − v Δt)} read bilinearly, which does not keep the mass (what is read is not
 * what left: PipeErosionTest measures it drifting past float rounding); the default
 * ({@link org.openworld.engine.erosion.hydraulic.PipeModel.Advection#FLUX}) sends each pipe the share of the cell's
 * load that it sends of its water, {@code s f Δt / (d₁ l²)}, so heights + load are kept to rounding. The paper's step
 * is kept as {@code SEMI_LAGRANGIAN} to compare.
 *
 * <p><b>Borders.</b> {@code PERIODIC} wraps (a generated tile). {@code APRON} is a block with a margin: past the edge
 * lies dry ground at the edge cell's height, so water and its load flow out and nothing flows in; the caller keeps
 * only the block inside the margin. An unbounded world erodes each block with an apron
 * ({@link org.openworld.engine.erosion.hydraulic.HydraulicErosion#block}): the block and its surroundings from the
 * same height source, so neighbours' aprons overlap; each pass reads a cell's neighbours, so the border's effect can
 * reach inwards by up to 4 cells a step, but it fades within tens of cells (an apron of 24 samples left a block's
 * edge within float rounding of a run over a far larger window, HydraulicBlockTest; 4 samples left 2.2 m), so two
 * neighbours with wide enough aprons meet at their seam. The world passes its level's samples with the apron, keeps
 * the returned block and its change (for its materials' b and a channels, as {@code ErosionCover} makes them).
 *
 * <p><b>Both sides.</b> {@link org.openworld.engine.erosion.hydraulic.GpuPipeErosion} runs the passes on float
 * textures (OpenGL 3.3, no compute shaders: macOS has none);
 * {@link org.openworld.engine.erosion.hydraulic.PipeErosion} is the same scheme on the CPU, operation for operation,
 * the reference the GPU is tested against and the step a machine without OpenGL runs ({@code heightmap}).
 *
 * <p><b>Cost.</b> GPU: 3 passes a step over the grid, 4 RGBA32F textures (64 bytes a cell: 16 MiB at 512²), at
 * start only. The tile (512² at 8 m, {@value org.openworld.engine.erosion.hydraulic.HydraulicErosion#TILE_STEPS}
 * steps, 450 passes): 29 to 66 s on llvmpipe with the shared two-core machine's load at 23, the {@code hydraulic}
 * stage of the start-up times; not yet measured on a hardware GPU. CPU reference: 14 to 55 s of wall time on the
 * same loaded machine.
 *
 * <p><b>Limits.</b> The pipes have no friction, so the sheet runs at the scheme's speed limit (l / Δt) and the
 * "velocity" is a rate of transport rather than a speed; the run is short, so the water does not reach the sea from
 * every valley, and the sediment it lays is what a few storms move, metres in the floors and tens of centimetres off
 * the slopes; the grid is the 8 m level, so a deposit is smooth over 8 m.
 */
package org.openworld.engine.erosion.hydraulic;

/**
 * Drainage analysis: where water runs on a height grid, and the measures that tell a landscape carved by rivers
 * from noise. GL-free; {@code openworld heightmap --stats} prints them for any world or imported map
 * ({@code docs/terrain.md}, "Measured against real landscapes").
 *
 * <p><b>Pits.</b> Water must reach an outlet (the grid's border, or on a periodic tile the sea), so every closed
 * depression is filled first: priority-flood with ε (Barnes, Lehman and Mulla 2014, "Priority-flood: an optimal
 * depression-filling and watershed-labeling algorithm"). From the outlets inwards, lowest cell first, a cell reached
 * from a cell c takes {@code max(h, nextUp(h_c))}, so it ends strictly above the cell that reached it: no flat and
 * no pit is left, and the order cells leave the queue is ascending in filled height. {@link
 * org.openworld.engine.drainage.CellQueue} is the queue: one {@code long} per cell, height bits over cell index, so
 * ties leave in a fixed order. O(n log n).
 *
 * <p><b>Flow directions (D8)</b> (O'Callaghan and Mark 1984). Each cell drains to the neighbour of the eight with the
 * steepest drop per metre, {@code (h_c − h_n) / d}, d the side or the diagonal; the fill guarantees one lies lower.
 *
 * <p><b>Drainage area and flow length.</b> Visiting cells highest first, each adds its area (its own cell included)
 * to its receiver's, and offers its longest upstream path plus the step to its receiver: A and L, the length of the
 * longest flow path from a divide, in O(n) ({@link org.openworld.engine.drainage.FlowNetwork}).
 *
 * <p><b>Measures</b> ({@link org.openworld.engine.drainage.DrainageStats}):
 * <ul>
 * <li><b>Concavity θ</b>, Flint's law {@code S = k_s A^−θ} (Flint 1974): log S against log A over the channel cells
 *     whose area lies in a fit range, binned a tenth of a decade and fitted by least squares through the bins'
 *     geometric means ({@link org.openworld.engine.drainage.LogFit}); slope S to the receiver on the filled heights,
 *     cells the fill raised left out. Real channels: θ 0.35–0.6 (Whipple 2004; Tucker and Whipple 2002). Spectral
 *     noise has no network to organise its slopes: θ near 0.</li>
 * <li><b>Hack's exponent h</b>, {@code L ∝ A^h} (Hack 1957), binned and fitted the same way over the same range:
 *     0.5–0.6 in real basins (Rigon et al. 1996: 0.57 ± 0.03).</li>
 * <li><b>Hypsometric integral</b> {@code (mean − min) / (max − min)} of the heights (Strahler 1952): 0.3–0.5 for
 *     mature, dissected relief, above 0.6 for young uplands.</li>
 * <li><b>Slope percentiles</b>, 10th/50th/90th, from central differences, degrees.</li>
 * <li><b>Drainage density</b>: channel length (cells draining at least the fit range's lower end, each counting its
 *     step to its receiver) per area, km/km².</li>
 * </ul>
 *
 * <p><b>Validation.</b> A surface built to {@code S = k A^−0.5} on a network gives θ within 0.05 of 0.5; a plane gives
 * parallel flow (no cell gathers two) and θ = 0. A real DEM, 3″ elevations of the Jacksboro fault in Tennessee's
 * ridge-and-valley Appalachians (USGS, as shipped in matplotlib's sample data; 403 × 344 cells of 74 × 93 m), gives
 * over 0.1–10 km² θ = 0.36 (R² 0.98) and h = 0.50, hypsometric integral 0.35, drainage density 1.9 km/km².
 *
 * <p><b>Limits.</b> D8 bends flow to eight directions, so on a plane the paths are parallel lines and on a cone the
 * area gathers in eight spokes (D∞, Tarboton 1997, would split it); lakes are filled, not kept; the fit range is a
 * parameter, and θ depends on it (the DEM gives 0.28 over 0.1–100 km², where few basins are that large).
 * Cost: O(n log n) for the fill, O(n) for the rest; measured on the shared two-core machine under load, routing
 * and measuring took 1.3–2.7 s for 512² and 3.5–4.8 s for 1024² (the slope percentiles' sort included), the
 * routing alone 0.5–0.8 s for 512² (the terrain's {@code wetness} stage).
 */
package org.openworld.engine.drainage;

/**
 * The terrain's first stage: heights. In: the world's settings ({@link org.openworld.engine.terrain.heights.TerrainSettings})
 * and a seed, or a map file. Out: heights at any level of detail, either a whole periodic tile with its pyramid
 * ({@link org.openworld.engine.terrain.heights.HeightPyramid}) or, for the unbounded world, the octave bands any
 * level's heights are summed from ({@link org.openworld.engine.terrain.heights.BandedHeights}). Nothing here knows
 * how the heights are drawn.
 *
 * <p><b>Generation (2.1).</b> {@link org.openworld.engine.terrain.heights.SpectralSynthesis} fills a spectrum with random
 * phases and amplitudes {@code A(ω) ∝ 1/ω^β} between two wavelength cut-offs and takes one inverse real 2D FFT
 * (JTransforms), then normalises to the relief: {@code h = relief · (n − seaFraction)}. Power then falls as
 * {@code ω^(−2β)}, which {@link org.openworld.engine.terrain.heights.PowerSpectrum} measures back. β = 1 is the paper's
 * literal 1/ω: each octave adds as much slope as the one before, and the result is crumpled; the default β = 2.2 lets
 * the large ranges dominate (mean slope 34°, close to alpine ground). The field is <em>periodic</em> — the inverse
 * DFT makes every edge continue into the opposite one — so copies of the tile meet without a seam, and the terrain
 * draws copies around the camera: the world has no edge. A map can be imported instead
 * ({@link org.openworld.engine.terrain.heights.HeightImport}: 16-bit PNG or float32 raw); it is not periodic and clamps.
 * Cost O(n² log n): about 0.2 s for 2048², 0.8 s for 4096² on two cores.
 *
 * <p><b>The unbounded world: heights made per level.</b> {@link
 * org.openworld.engine.terrain.heights.BandedHeights} makes what the paper's conclusion proposes: each resolution directly,
 * with no full-resolution map. The spectrum is cut into octave bands, band k holding {@code 1/(4 d_k) ≤ ω < 1/(2 d_k)}
 * for level k's spacing {@code d_k = 2^k · spacing}; each band ({@link org.openworld.engine.terrain.heights.OctaveBand}) is
 * a 512² periodic tile of samples d_k/2 apart, synthesised as above with its coefficients times {@code E^(β−1)} (E
 * the tile's side: the density ω^−2β continues across tiles of different sizes) and divided by {@code sinc⁴}, so that
 * a cubic B-spline through its samples reproduces the band exactly, its images weakened to at most 1.2 % of the
 * amplitude. Level L is {@code h_L(x, z) = mean + Σ_{k ≥ L} band_k(R_k (x, z) + o_k)}, each band turned (R_k) and
 * shifted (o_k) per seed so that the bands' periods never line up (the whole repeats beyond 10 000 km: the
 * arithmetic is in BandedHeights). Cost: nine 512² FFTs and 9 MiB when the world is made (0.3 s); then 16 samples
 * per band per height, 0.75–1.2 s for the 2000² samples of the 64 km overview on two cores. Limits: each band alone
 * repeats on its lattice (131 km for the 1–2 km band, which carries 80 % of the variance at β = 2.2); the relief is
 * scaled by the standard deviation (±3σ), so a few per mille of the ground lie outside it.
 *
 * <p><b>Pyramid (2.5).</b> {@link org.openworld.engine.terrain.heights.HeightPyramid#build} low-passes each level with the
 * binomial kernel (1 4 6 4 1)/16 (a Gaussian of σ ≈ 1 sample, response cos⁴(πf)) and keeps every other sample.
 * Without the filter a ridge finer than the new spacing would alias into a false hill at the coarse level; with it,
 * the coarse level shows the smoothed ridge and the switch between levels pops less.
 */
package org.openworld.engine.terrain.heights;

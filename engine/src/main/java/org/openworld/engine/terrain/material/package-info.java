/**
 * The terrain's fourth stage: the surface. In: the heights (the pyramid's finest levels) and the material
 * settings. Out: textures the terrain's programs read: the synthesised material textures
 * ({@link org.openworld.engine.terrain.material.TerrainTextures}), the height, slope and snow maps
 * ({@link org.openworld.engine.terrain.material.TerrainMaps}) and the far material's bake
 * ({@link org.openworld.engine.terrain.material.FarMaterial}).
 *
 * <p><b>Materials (2.2).</b> Grass low, rock between and on steep slopes, snow high, blended smoothly; the snow comes
 * from {@link org.openworld.engine.terrain.material.SnowMap}: snow with probability {@code p = clamp((n − base)/(full − base))}
 * of the normalised height n, then a morphological opening and closing (figures 1b, 2). Figure 1a's plain altitude
 * bands are {@code materials.snow-mode=altitude-bands}. On an eroded tile the erosion's sediment lies as alluvium
 * and scree, its bared bed as rock, and snow gathers on the sediment
 * ({@link org.openworld.engine.terrain.material.ErosionCover}). The slope comes from a gradient map of the finest level, so
 * coarse patches still shade with fine slopes; the tangent frame {@code T = (1, ∂h/∂x, 0)}, {@code B = (0, ∂h/∂z, 1)}
 * carries normal and gloss maps (figure 3) and is shown by {@code terrain-debug.colouring=tangent-space} (figure 4).
 * All textures are synthesised by {@link org.openworld.engine.terrain.material.TerrainTextures} (periodic noise, a recipe per
 * material, the packing into RGBA8); two scales are blended to hide the tiling the paper complains of in section 6.
 * {@code materials.tiling=quilted} does what the paper proposes, image quilting (Efros and Freeman 2001), made
 * aperiodic as quilted Wang tiles (Cohen et al. 2003, {@link org.openworld.engine.terrain.material.WangTiles}): 16
 * tiles cut from each texture along minimum-error seams ({@link org.openworld.engine.terrain.material.ImageQuilting}),
 * edges matched by colour, laid by a hash of the tile grid: one lookup per scale, 16 times the texture memory.
 * {@code materials.tiling=stochastic} removes the repeat (Heitz and Neyret 2018): a triangle grid in skewed space,
 * each corner shifting the texture by a hash of its lattice point, the three lookups blended by barycentric weights w
 * around the texture's mean m as {@code m + Σ w_i (x_i − m) / sqrt(Σ w_i²)}, which keeps the contrast; three times
 * the lookups. How much each still repeats: docs/terrain.md, section 4.
 *
 * <p><b>The sky the relief hides.</b> Shadowed ground is lit by the sky's irradiance for its normal,
 * E(n) from nine spherical-harmonic factors (the sky system's); {@link org.openworld.engine.terrain.material.HorizonSearch}
 * takes out what the relief hides: along 8 azimuths the horizon's rise above the tangent plane α, searched over the
 * pyramid to 3 km, gives the visible share {@code V = (1/8) Σ cos² α}, and the light becomes
 * {@code V · E(n) + (1 − V) · E_hidden}, E_hidden that of terrain under the sky and half the sun. One way for every
 * source, on the GPU ({@code shaders/terrain/material/horizon.glsl}): the tile's once at start over its level of at
 * most 512² samples ({@link org.openworld.engine.terrain.material.TileSky}), the streamed world's per block; stored as the snow
 * texture's second channel, so no lookup is added. Limits:
 * gullies narrower than two samples, a uniform sky, occluders lit the same everywhere.
 *
 * <p><b>Cliffs.</b> Projected from above, texture coordinates (x, z) stretch a face of slope a by
 * 1 / cos a down its fall line (2.9 times at 70°). {@code materials.cliffs=triplanar} projects the rock three ways in
 * the near program, onto (x, z), (z, y) and (x, y), blended by the geometric normal with weights
 * {@code w_i = |n_i|^8 / Σ_j |n_j|^8}: each plane shows the surface where it faces it (at most √3 stretch where it
 * weighs most, 1.06 on a 70° face), and the planes mix only between about 35° and 55° of slope. The normal map's
 * slope is read along each plane's texture axes and swizzled into the terrain's frame T, B: on (z, y) it is
 * {@code (±s_v, s_u)}, on (x, y) {@code (s_u, ±s_v)}, the sign that of the frame vector's rise, so bumps stay lit from
 * the sun's side. Cost: 8 more texture reads in the near program (20 instead of 12), so the default stays
 * {@code planar}; the near programs are compiled with or without {@code MAT_TRIPLANAR}. Limits: the far material is baked over
 * (x, z) and keeps a texel every 2 m / cos a down a far cliff; inside the blend band two patches of rock show
 * through each other.
 *
 * <p><b>Near and far materials.</b> Far away the mip maps average most of a material away, so
 * {@link org.openworld.engine.terrain.material.FarMaterial} bakes it once: steps 1–3 of {@code material.glsl} per texel of two
 * textures over the tile (albedo and gloss, detail slope; 2 m texels by default). Patches are ordered nearest first
 * ({@link org.openworld.engine.terrain.mesh.PatchOrder}: early depth rejection); those whose box lies beyond
 * D = {@code materials.far-texels} baked texels run a far program of two lookups, the nearer ones the full material, faded into the
 * baked one between 0.7 D and D so the two meet without a seam
 * ({@link org.openworld.engine.terrain.TerrainShading}). The choice is made on the CPU: on a software rasteriser a
 * branch runs both sides. Cost: the far program is about a quarter of the near one per pixel; the bake is one pass at
 * start. Limit: edges finer than a texel are softer far away.
 */
package org.openworld.engine.terrain.material;

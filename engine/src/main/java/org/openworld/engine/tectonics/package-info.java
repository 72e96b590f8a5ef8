/**
 * Large-scale structure for the unbounded world (opt-in, {@code terrain.ranges}): mountain ranges, foothills and
 * plains tens of kilometres across, which the spectral bands alone (wavelengths up to 2 km) cannot give. A low
 * frequency "tectonic" field t(x, z), two octaves of value noise on lattices 32 and 16 km apart (the second turned
 * 0.6 rad), sets how much of the bands' relief each place keeps and how low its mean lies:
 * <pre>
 *   a = 0.2 + 0.8 · smoothstep((t + 0.3) / 0.4)           (0.2 on plains, t ≤ −0.3; 1 in ranges, t ≥ 0.1)
 *   h = mean − drop · (1 − a) + a · Σ_k band_k            (drop = 0.25 · relief: plains are lowlands)
 * </pre>
 * Every level of the world multiplies its own bands by the same a, so level L + 1 is still level L without band L,
 * and a is smooth at 16 km, so it adds no frequency a level's samples cannot hold. Pure function of position and
 * seed (a hashed lattice, {@code StrictMath}): blocks agree whatever order they are made in. Cost: two value-noise
 * look-ups (eight hashes) per height, next to 16 B-spline taps per band for nine bands. Limits: the ranges are
 * blobs, not the long belts that plate boundaries raise (no domain warping or ridged bands yet). With
 * {@code terrain.erosion} the world is eroded after this field shapes it ({@link org.openworld.engine.erosion}): the
 * uplift follows the shaped heights, so ranges erode steep and plains gentle, and the coarsest levels' rivers run
 * from the ranges across the plains.
 */
package org.openworld.engine.tectonics;

/**
 * Trees: conifers scattered on the terrain around the viewer, drawn instanced in the picture, the sun's shadow maps
 * and the water's reflection. Off by default ({@code --set system.trees=on}). How it was built, step by step, as an
 * example of a system that draws in more than one pass: {@code docs/adding-a-system.md}, "A second system: trees in
 * every pass".
 *
 * <p><b>Placement</b> ({@link org.openworld.engine.trees.TreePlacement}): a jittered grid over the plane, each cell's
 * tree (kept with probability {@code density · cell²}, at a random point of the cell) drawn from a hash of
 * {@code engine.seed} and the cell, so the same ground always grows the same trees. A tree stands where the world's
 * {@link org.openworld.engine.core.HeightField} is above the {@link org.openworld.engine.environment.WaterLevel} plus
 * {@code trees.shore-margin}, below the {@link org.openworld.engine.environment.SnowLine}'s start, and no steeper
 * than {@code trees.max-slope}; without a water level or a snow line that rule is left out. The trees within 1.25
 * view distances of the viewer are placed again when the viewer has moved a quarter of the view distance.
 *
 * <p><b>Drawing</b>: one shape for every tree ({@link org.openworld.engine.trees.TreeShape}, a trunk and three
 * cones, 48 triangles) and one record per tree (foot, height, turn, tint), drawn with
 * {@code Mesh.drawInstances}. The records are grouped by tile of 200 m, and the tiles' boxes go to the culling
 * system as a {@code Cullable}: each pass camera (the viewer, the mirror, each shadow cascade) draws only the tiles
 * it sees, one call per run of neighbouring visible tiles. The trees are lit as the terrain is (Lambert sun, wrapped
 * a little for the needles, times {@code sunVisibility} from the shadow maps; the sky's hemisphere light; the
 * aerial perspective; the display transform) and shrink into the ground over the last fifth of
 * {@code trees.view-distance}, measured from the viewer's eye ({@code viewerPos()}) in every pass, so they leave the
 * picture, the reflection and the shadows together.
 *
 * <p><b>Cost</b>, measured with {@code openworld bench --path assets/paths/valley.path --size 960x540 --set
 * system.trees=on} on Mesa llvmpipe: 16 000 trees within reach at the default 30 a hectare; per frame 5 500 trees
 * drawn in the picture, 3 700 in the reflection and 45 000 over the four shadow cascades (mostly the two far ones,
 * whose boxes are widest), 2.6 M triangles in all, about half the frame's. The trees' share of the frame is 390 ms of
 * 2 530 (llvmpipe rasterises on the CPU, so its CPU times hold the drawing). Placing the trees takes 40 ms of CPU
 * ({@code trees.place-ms} in the counters), on the render thread, once per 375 m the viewer moves.
 *
 * <p><b>Limits</b>: one shape for every tree, no levels of detail (a far tree costs its 48 triangles, shrunk; a real
 * forest would swap to impostors); the placement is a hitch on the render thread (a worker thread would hide it);
 * the foot follows the finest height field, while the terrain draws coarser levels far away, where a tree may stand a
 * little into or above the drawn ground (the trunk reaches 4% of the height below its foot to hide most of it); trees
 * do not move in the wind; no tree is placed under water, on snow or on a cliff, but the snow line is a height, so a
 * snowy north face below it may still hold trees; a light box reaches towards the sun only as far as the highest
 * caster the culling system knows of, the tree tops included.
 */
package org.openworld.engine.trees;

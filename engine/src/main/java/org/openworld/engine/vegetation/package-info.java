/**
 * Vegetation: forests, lone trees and bushes placed from the land around the viewer, drawn instanced in the picture,
 * the sun's shadow maps and the water's reflection, with a full and a simplified shape per kind. On by default
 * ({@code --set system.vegetation=off} removes it). How the trees were built, step by step, as an example of a system
 * that draws in more than one pass: {@code docs/adding-a-system.md}, "A second system: trees in every pass"; the
 * techniques with pictures: {@code docs/vegetation.md}.
 *
 * <p><b>Placement</b> ({@link org.openworld.engine.vegetation.TreePlacement}, {@link
 * org.openworld.engine.vegetation.PlacementField}): a jittered grid over the plane in 200 m tiles, each cell's plant
 * (kept with probability {@code density · cell² · field(x, z)}, at a random point of the cell) drawn from a hash of
 * {@code engine.seed} and the cell, so the same ground always grows the same plants whichever tile is placed first. The
 * field is value noise made into forests with edges and clearings, times the moisture (the world's {@link
 * org.openworld.engine.environment.Moisture} where one is published; a stand-in from the shore, hollows and sun-facing
 * slopes otherwise), times the chance of no snow, times a tree line that thins the forest over a band below it, deeper
 * on slopes turned from the sun. A plant stands where the world's {@link org.openworld.engine.core.HeightField} is
 * above the {@link org.openworld.engine.environment.WaterLevel} plus {@code vegetation.shore-margin}, below the tree
 * line (half-way up the {@link org.openworld.engine.environment.SnowLine}'s fringe, where snow is as likely as not),
 * and no steeper than {@code vegetation.max-slope}; towards the line trees shrink to half their height. The kind
 * follows the forest's edge, the height and the moisture: bushes at the edges and the tree line, broadleaf trees low,
 * conifers high. The tiles within 1.25 view distances of the viewer are placed again, on a worker thread, when the
 * viewer has moved a quarter of the view distance; only the tiles the move brings in are new work.
 *
 * <p><b>Far from the origin</b>: no foot is kept as a float of the world's x and z (1 m apart 10 000 km out). A tile
 * holds its feet from its own corner, a layout from its centre (the corner of the tile under the viewer, in double);
 * each pass hands the shader that centre from the {@link org.openworld.engine.origin.RenderOrigin} ({@code uPlaced},
 * rounded to float once) and the swing's phase there reduced modulo a turn ({@code uSway}), so every sum on the GPU
 * is of numbers a few kilometres at most. The data path: tile (corner, double; feet, float) → layout (centre, double;
 * feet and boxes, float) → {@code uPlaced = centre − origin} → the foot from the origin. The culling gets the boxes
 * with the centre as their one copy's offset.
 *
 * <p><b>Drawing</b> ({@link org.openworld.engine.vegetation.TreeDraw}): per kind a full shape within
 * {@code vegetation.lod-distance} (92 to 268 triangles), a simplified one to {@code vegetation.impostor-distance} (16
 * to 42), and beyond it an impostor, one card ({@link org.openworld.engine.vegetation.ImpostorDraw}); each switch
 * cross-faded by a 4 × 4 ordered dither over ±10 % of its distance; the shadow cascades switch hard at the same
 * distances (the far cascades draw cards facing the sun) and leave the far bushes out; the reflection draws the cards
 * only. One instanced call per kind, representation and run of neighbouring visible tiles
 * ({@code Mesh.drawInstances}); the tiles' boxes go to the culling system as a {@code Cullable}. The leaves are a
 * pattern of the shape's coordinates (clumps that tilt the normal); the bark a texture synthesised at start from the
 * ground's periodic noise ({@link org.openworld.engine.vegetation.BarkTextures}, uploaded mipmapped by
 * {@link org.openworld.engine.vegetation.PlantMaps}; 1.3 MiB), wrapped round the stems with its relief's normals,
 * on the meshes and in the impostors' bake alike; all lit as the terrain is (wrapped
 * Lambert sun times {@code sunVisibility}, the sky's light, the aerial perspective, the display transform) plus the
 * light through the leaves against the sun; crowns lean and swing in the
 * {@link org.openworld.engine.environment.Wind}. Plants shrink into the ground over the last fifth of
 * {@code vegetation.view-distance}; the fades and the switches are measured from the viewer's eye
 * ({@code viewerPos()}) in every pass, so the picture, the reflection and the shadows agree.
 *
 * <p><b>Impostors</b> ({@link org.openworld.engine.vegetation.ImpostorAtlas}): at start each kind's full shape is
 * drawn orthographically from 9 × 9 directions over the upper hemisphere, laid out hemi-octahedrally (the hemisphere
 * folded onto the octahedron |x| + |y| + |z| = 1, that onto a square: {@code d = (p.x, 1 − |p.x| − |p.z|, p.z)}
 * normalised for the square's point p turned 45°), into 64-pixel frames of albedo and coverage, and of normal and
 * depth. A plant's card stands square to the direction from the plant to the eye (turned and narrowed back into the
 * plant's own space) and blends the three frames nearest it, weighted barycentrically on the grid's triangle holding
 * the direction; each frame is read where the eye's ray meets its plane, {@code s = q − v (q·f) / (v·f)}, and puts
 * the surface back at {@code s + f · depth}; the card is lit per pixel as the meshes are, at the blended point, and
 * sways as they do ({@code shaders/vegetation/sway.glsl}: the corners swayed, the sway taken back out per pixel).
 * Cost: 486 draws at start; one 1152 × 1728 RGBA8 atlas and its depth buffer (15.2 MiB); two triangles per plant and
 * six texture reads per pixel.
 *
 * <p><b>Past the plants' reach</b> ({@link org.openworld.engine.vegetation.FarForest}): the far ground's material
 * ({@code shaders/common/forest.glsl}, read by the terrain's far program) mixes in the canopy's colour by the share of
 * the ground the crowns hide, {@code 1 − exp(−ρ Σ p_k a_k)} (ρ plants per m² from the field, p_k each kind's share,
 * a_k its crown from above, measured on the impostor's top view), over a 32 km window around the viewer made on the
 * worker; it fades in over the last fifth of the view distance as the plants shrink away, measured as they are, so
 * a forest keeps its place and colour to the horizon. The colour is a geometric-optical canopy (after Li and
 * Strahler 1992) lit as the plants are: crowns seen {@code 1 − exp(−τ F(θ_view))}, {@code F = 1 + side/top · tan θ}
 * (the kinds' outlines, {@link org.openworld.engine.vegetation.FarForest#sideOverTop}), the crowns' sun by the
 * wrapped Lambert sphere's phase law and the sun's way through their neighbours, the gaps' ground in their shadows
 * but at the hot spot; about 60 arithmetic operations per far-ground pixel.
 *
 * <p><b>Cost</b> ({@code docs/vegetation.md}, "Cost"): on {@code valley.path} at 1280 × 720 on llvmpipe, 3 461 plants
 * within reach, 786 drawn in the picture; the vegetation's spans 29 ms of a 2 s frame on a heavily loaded machine
 * (1.5 %), frames with and without it within that machine's noise (0.89 and 0.99); 16 MiB of textures at start.
 *
 * <p><b>Limits</b>: past the view distance the forests are a colour of the ground, flat (no height of their own), a
 * little darker than the drawn forest seen at grazing angles; an impostor's outline is dithered where its three views
 * disagree (a speckled rim seen close up); the foot follows the finest height field, while the terrain draws coarser
 * levels far away, where a plant may stand a little into or above the drawn ground (the trunk reaches 4 % of the
 * height below its foot to hide most of it); the tree line follows the snow line's height, so a snowy north face below
 * it may still hold trees; a light box reaches towards the sun only as far as the highest caster the culling system
 * knows of, the tree tops included.
 */
package org.openworld.engine.vegetation;

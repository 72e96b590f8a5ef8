/**
 * Grass near the eye: tufts of blades generated on the GPU from their instance index, on a grid of cells fixed to the
 * world, where the land grows grass, thinning into the ground's own grass texture with distance. On by default
 * ({@code --set system.grass=off} removes it); the pictures, the cost and the limits: {@code docs/vegetation.md},
 * "Grass".
 *
 * <p><b>The field</b> ({@link org.openworld.engine.grass.GrassField}): every metre on the world's grid around the
 * viewer, the ground's height and the grass's share, 0 to 1:
 * <pre>
 *   share = ground(x, z, h) · (1 − snow.chanceAt(h))     where h ≥ water + 0.3 m and |∇h| ≤ tan(grass.max-slope)
 *   share = 0                                            elsewhere (the water's rim, rock, the full snow)
 * </pre>
 * {@code ground} is the vegetation's {@link org.openworld.engine.vegetation.PlacementField#ground} (the land's
 * moisture, from the same field the trees grow from, published by the vegetation; 1 without it; not its tree line:
 * grass grows above the trees), and
 * {@code chanceAt} the {@link org.openworld.engine.environment.SnowLine}'s: grass thins where the snow lies in
 * patches and is gone above its full line. A worker thread makes it again when the viewer has moved a quarter of
 * {@code grass.distance}; the GPU reads it as a texture.
 *
 * <p><b>The tufts</b> ({@link org.openworld.engine.grass.GrassRuns}, {@code shaders/grass/grass.vert}): the plane is
 * cut into cells of {@code c = sqrt(4 / grass.density)} metres, one tuft of four blades each, indexed
 * {@code floor(x / c)} on the world's grid. Blocks of 8 × 8 cells within {@code grass.distance} whose boxes meet the
 * frustum are drawn, a row's neighbouring blocks in one {@code glDrawArraysInstanced} with no vertex data: instance
 * {@code i} is the cell {@code (i mod wide, i div wide)} from the run's first cell, vertex {@code v} the corner
 * {@code v mod 9} of blade {@code v div 9}. A hash of the cell's integer index and {@code engine.seed} places the
 * tuft in its cell and gives each blade its spot, turn, height, tint and thinning threshold, so a blade never moves
 * (or swims) as the viewer does. A blade is drawn while {@code hash < share · fade}, {@code fade} falling from 1 to 0
 * over the last 30 % of the distance: blades drop out one by one, the same ones every frame, into the ground's grass
 * texture. Nothing is blended, so the depth and the temporal anti-aliasing's reprojection stay exact. Before they thin,
 * from 40 to 70 % of the distance, the blades take on the ground's look, {@code mix(ground, blade, own)} with
 * {@code own} falling 1 to 0 (a smoothstep): {@code ground} the terrain's grass from afar
 * ({@link org.openworld.engine.terrain.material.GrassAlbedo}: the texture's mean albedo and squared gloss) lit on the
 * ground's normal from the field, with the sky's sheen {@code (0.04 + 0.96 (1 − n·v)^5) · gloss²} at a grazing look.
 * Each blade's spine bends as the square of its height by its own lean plus the
 * {@link org.openworld.engine.environment.Wind} (a fifth of the cloud layer's near the ground), swinging at 1 Hz in
 * waves across the meadow.
 *
 * <p><b>Light</b>: the terrain's, so the blades sit in their ground: wrapped Lambert sun times {@code sunVisibility}
 * (the shadow cascades), the sky's hemisphere light, light through the blade against the sun, the air's
 * perspective and the display transform; the normal leans to the sky, so a meadow lights as a layer. The contact
 * shadow: the light at height {@code t} (0 root, 1 tip) is {@code 1 − c (1 − t)} of the tip's, with
 * {@code c = 0.55 (1 − exp(−ρ / 24))}, {@code ρ = grass.density · share · fade} the blades per m² about the root: the
 * default meadow's roots get 65 % of the light, a sparse one's nearly all.
 *
 * <p><b>Far from the origin</b>: the runs' corners and the field's first sample are handed to the shader from the
 * {@link org.openworld.engine.origin.RenderOrigin} (in double, then float), the swing's phase there reduced modulo a
 * turn; the cells' indices are 32-bit integers up to 2^24 m at the densest setting ({@code GrassFieldTest}).
 *
 * <p><b>Cost</b> (the default 24 blades/m², 40 m): about 10 000 tufts drawn at walk height on a meadow (360 000
 * vertices, 120 000 triangles, most folded away by the thinning), one draw call per row of blocks; the field 110 ×
 * 110 samples, made on the worker. Per drawn blade's vertex two more field reads (the ground's normal) and an
 * exponential (the contact shadow); per pixel of a blade past 40 % of the distance one cube map read (the sheen).
 * The measured frame times: {@code docs/vegetation.md}, "Grass".
 *
 * <p><b>Limits</b>: blades are drawn in the picture only (not in the shadow maps: they cast no shadow, nor in the
 * water's reflection); the field's 1 m bilinear ground and the terrain's triangles may differ by centimetres (the root
 * reaches 5 cm under it); the ground texture's rock-by-height band (terrain.material) is not in the field, so grass
 * may stand on rock there below the snow line; a tuft stands for a clump, four blades 4 to 8 cm wide. The far blades
 * take on the ground's mean colour, not its macro patches; the ground under dense grass is not darkened (the contact
 * shadow is the blades' own).
 */
package org.openworld.engine.grass;

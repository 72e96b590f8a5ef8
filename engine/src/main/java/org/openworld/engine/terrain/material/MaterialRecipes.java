package org.openworld.engine.terrain.material;

import java.util.SplittableRandom;
import org.openworld.engine.texture.MaterialFields;
import org.openworld.engine.texture.PeriodicNoise;

/**
 * What each terrain material is made of: the recipes that turn {@link PeriodicNoise periodic noise},
 * {@link PeriodicCells cells} and stamped shapes into a {@link MaterialFields} of colour, relief and gloss (paper 2.2).
 * Relief heights are in texels; the normal comes from their derivatives in {@link MaterialEncoding}.
 *
 * <ul>
 *   <li><b>grass</b>: a soil layer of fine noise under thousands of stamped blades (random direction, slight curl,
 *       tapered, rising from root to tip), denser in low-frequency clumps; blade colour from dark green to
 *       yellow-green, drier (olive) in large patches, roots in shadow;</li>
 *   <li><b>rock</b>: blocks from a periodic Voronoi diagram of warped coordinates, each a tilted facet chipped round
 *       at its edges, cracks between them (open in places) and finer fractures inside; rough 1/f^2.6 relief and
 *       shallow ledged strata on top; grey to brown per block and stratum, dark cracks, a little lichen; cracks hold
 *       water and shine;</li>
 *   <li><b>snow</b>: soft 1/f³ drifts and a fine grain; near white, blue in the hollows (light that has travelled
 *       through snow), sparkling texels of full gloss where the grain field peaks.</li>
 * </ul>
 *
 * <p><b>Tileable.</b> Every ingredient is periodic over the tile: the noise by construction, the strata run a whole
 * number of cycles, the cells wrap, and grass blades are stamped with wrapped texel indices.
 *
 * <p><b>Cost.</b> Grass: two noise pairs and about n²/9 blades of 20 to 50 discs each, the most texel writes of the
 * three. Rock: four noise pairs and two cell queries per texel. Snow: two noise pairs and one pass. Grass and rock
 * take about as long as each other, snow a fifth of either (measured at 512², JIT warm); {@link TerrainTextures}
 * gives the total. A recipe draws all its random numbers from the one stream it is given, in a fixed order, so a
 * seed fixes the result.
 *
 * <p><b>Limits.</b> The colours are hand-tuned reflectances, not measured ones; blades are seen from above only
 * (no parallax); the rock has no overhangs, a height field cannot.
 */
final class MaterialRecipes {

    /** Strata of the rock per tile: 7 layers of 39 cm at the default 2.7 m tile, bedding planes in a boulder. */
    private static final int STRATA = 7;
    /** Height of a grass blade's tip over the soil, texels per relief unit: blades stand 3 to 6 texels. */
    private static final double GRASS_RELIEF = 6;
    /** Relief of the snow drifts, texels per standard deviation: swells of a few centimetres over tens. */
    private static final double SNOW_DRIFT = 8;
    /** Rock blocks per tile side: 5² facets of 54 cm at the default tile, the size of fractured slabs. */
    private static final int ROCK_BLOCKS = 5;
    /** Finer fractures per tile side: 13², about 21 cm apart. */
    private static final int ROCK_FRACTURES = 13;
    /** Displacement of the crack pattern by the warp noise, texels per standard deviation: bends the edges. */
    private static final double ROCK_WARP = 9;

    private final int n;
    private final int mask;
    private final PeriodicNoise noise;

    /** Recipes for tiles of {@code n}² texels, {@code n} a power of two. */
    MaterialRecipes(int n) {
        this.n = n;
        this.mask = n - 1;
        this.noise = new PeriodicNoise(n);
    }

    /** The recipe of one material. */
    MaterialFields make(TerrainTextures.Material m, SplittableRandom rng) {
        return switch (m) {
            case GRASS -> grass(rng);
            case ROCK -> rock(rng);
            case SNOW -> snow(rng);
        };
    }

    // ---- grass --------------------------------------------------------------------------------------------------

    MaterialFields grass(SplittableRandom rng) {
        int nn = n * n;
        double[][] low = noise.pair(rng, PeriodicNoise.band(1.5, 10, 2.0));     // clump density, dryness
        double[][] soil = noise.pair(rng, PeriodicNoise.band(12, 200, 1.0));    // soil relief, soil colour
        double[] clump = low[0];
        double[] dry = low[1];
        float[] height = new float[nn];
        float[] tone = new float[nn];
        float[] along = new float[nn];
        float[] litter = new float[nn];
        for (int i = 0; i < nn; i++) {
            height[i] = (float) (0.08 + 0.03 * soil[0][i]);
            along[i] = -1; // soil, no blade
            litter[i] = (float) smoothstep(-0.5, 1.5, soil[1][i]);
        }
        // 1. blades, stamped as discs along a curling centre line; the higher one wins where they cross
        int blades = nn / 9;
        for (int b = 0; b < blades; b++) {
            double x = rng.nextDouble() * n;
            double y = rng.nextDouble() * n;
            double accept = 0.35 + 0.65 * smoothstep(-1.3, 0.9, clump[index((int) x, (int) y)]);
            double angle = rng.nextDouble() * 2 * Math.PI;
            double curl = (rng.nextDouble() - 0.5) * 0.08;          // rad per texel
            double length = 9 + 15 * rng.nextDouble();              // texels: 4.7 to 12.5 cm seen from above
            double width = 0.8 + 0.7 * rng.nextDouble();            // half width at the root, texels
            double tip = 0.55 + 0.45 * rng.nextDouble();            // height of the tip, relief units
            float bladeTone = (float) rng.nextDouble();
            if (rng.nextDouble() > accept) {
                continue;
            }
            // walk the centre line in half-texel steps, turning the direction by the curl at each step
            double dirX = Math.cos(angle) * 0.5;
            double dirY = Math.sin(angle) * 0.5;
            double turnCos = Math.cos(curl * 0.5);
            double turnSin = Math.sin(curl * 0.5);
            for (double s = 0; s <= length; s += 0.5) {
                double t = s / length;
                double halfWidth = width * Math.sqrt(1 - t) + 0.25;   // tapering to a point
                double top = 0.25 + (tip - 0.25) * t * (2 - t);        // rising, levelling off at the tip
                stampBlade(x, y, halfWidth, top, bladeTone, (float) t, height, tone, along);
                x += dirX;
                y += dirY;
                double turned = dirX * turnCos - dirY * turnSin;
                dirY = dirX * turnSin + dirY * turnCos;
                dirX = turned;
            }
        }
        // 2. colour: blades from dark to yellowish green, drier patches olive; soil brown with dead litter
        float[] r = new float[nn], g = new float[nn], bl = new float[nn], gloss = new float[nn];
        for (int i = 0; i < nn; i++) {
            double cr, cg, cb;
            if (along[i] < 0) {
                double l = litter[i];
                cr = mix(0.035, 0.10, l);
                cg = mix(0.030, 0.085, l);
                cb = mix(0.015, 0.035, l);
                gloss[i] = 0.06f;
            } else {
                double t = tone[i];
                double d = 0.75 * smoothstep(0.2, 1.8, dry[i]);
                cr = mix(mix(0.030, 0.085, t), 0.16, d);
                cg = mix(mix(0.075, 0.165, t), 0.15, d);
                cb = mix(mix(0.012, 0.030, t), 0.045, d);
                if (t > 0.96) { // a dead blade here and there: straw
                    cr = 0.24;
                    cg = 0.20;
                    cb = 0.10;
                }
                double shade = 0.5 + 0.6 * along[i];   // roots sit in the shadow of the canopy
                cr *= shade;
                cg *= shade;
                cb *= shade;
                gloss[i] = (float) (0.22 + 0.2 * along[i]);
            }
            double clumpLight = 0.88 + 0.12 * clump[i];
            r[i] = (float) (cr * clumpLight);
            g[i] = (float) (cg * clumpLight);
            bl[i] = (float) (cb * clumpLight);
            height[i] *= GRASS_RELIEF;
        }
        return new MaterialFields(r, g, bl, height, gloss);
    }

    /** One disc of a blade: texels within {@code radius} of (cx, cy) take the blade where it is the higher. */
    private void stampBlade(double cx, double cy, double radius, double top, float bladeTone, float t,
                            float[] height, float[] tone, float[] along) {
        int x0 = (int) Math.floor(cx - radius);
        int x1 = (int) Math.floor(cx + radius);
        int y0 = (int) Math.floor(cy - radius);
        int y1 = (int) Math.floor(cy + radius);
        for (int y = y0; y <= y1; y++) {
            for (int x = x0; x <= x1; x++) {
                double dx = x + 0.5 - cx;
                double dy = y + 0.5 - cy;
                double d2 = (dx * dx + dy * dy) / (radius * radius);
                if (d2 > 1) {
                    continue;
                }
                float h = (float) (top + 0.06 * (1 - d2)); // rounded across: a midrib catches the light
                int i = index(x, y);
                if (h > height[i]) {
                    height[i] = h;
                    tone[i] = bladeTone;
                    along[i] = t;
                }
            }
        }
    }

    // ---- rock ---------------------------------------------------------------------------------------------------

    MaterialFields rock(SplittableRandom rng) {
        int nn = n * n;
        double[][] relief = noise.pair(rng, PeriodicNoise.band(2, 160, 2.6));   // rough relief, colour variation
        double[][] fine = noise.pair(rng, PeriodicNoise.band(40, 256, 1.0));    // grain, lichen
        double[][] warp = noise.pair(rng, PeriodicNoise.band(2, 10, 2.0));      // bends the cracks (x, y displacement)
        double[][] low = noise.pair(rng, PeriodicNoise.band(1, 4, 2.0));        // strata warp, where cracks are open
        PeriodicCells blocks = new PeriodicCells(rng, n, ROCK_BLOCKS);
        PeriodicCells fractures = new PeriodicCells(rng, n, ROCK_FRACTURES);
        double[] layerTone = new double[STRATA];
        for (int k = 0; k < STRATA; k++) {
            layerTone[k] = rng.nextDouble();
        }
        float[] r = new float[nn], g = new float[nn], b = new float[nn], height = new float[nn], gloss = new float[nn];
        double blockSize = (double) n / ROCK_BLOCKS;
        for (int y = 0; y < n; y++) {
            for (int x = 0; x < n; x++) {
                int i = y * n + x;
                // 1. blocks: Voronoi cells of warped (still periodic) coordinates, each a tilted plane, chipped
                //    round at its edges; cracks between them, open in some places and closed in others
                double wx = x + 0.5 + ROCK_WARP * warp[0][i];
                double wy = y + 0.5 + ROCK_WARP * warp[1][i];
                int c = blocks.nearest(wx, wy);
                double edge = blocks.edgeDistance();
                double facet = blocks.base[c] + blocks.slopeX[c] * blocks.dx + blocks.slopeY[c] * blocks.dy;
                double rim = 1 - smoothstep(0, 0.3 * blockSize, edge);
                double chip = -0.1 * blockSize * rim * rim;
                double open = smoothstep(-0.8, 0.4, low[1][i] + 0.5 * relief[1][i]);
                double crack = open * (1 - smoothstep(0.4, 1.4 + 1.2 * open, edge));
                // finer fractures inside the blocks, fainter, and only some of them
                fractures.nearest(wx * 1.03 + 17, wy * 1.03 + 5);
                double hairline = 0.6 * smoothstep(0.2, 0.9, warp[0][i] * warp[1][i] + 0.3)
                        * (1 - smoothstep(0.3, 1.1, fractures.edgeDistance()));
                crack = Math.max(crack, hairline);
                // 2. strata: a whole number of layers along v, so periodic; a shallow ledge per layer
                double u = (double) STRATA * y / n + 0.45 * low[0][i];
                int layer = Math.floorMod((int) Math.floor(u), STRATA);
                double f = u - Math.floor(u);
                double ledge = smoothstep(0, 0.08, f) * (1 - 0.7 * f);
                height[i] = (float) (facet + chip + 2.0 * ledge + 3.0 * relief[0][i] + 0.25 * fine[0][i]
                        - 3.0 * crack);
                // 3. colour: grey, browner in some strata and blocks, streaked, dark cracks, a little lichen
                double brown = 0.35 * blocks.tone[c] + 0.35 * layerTone[layer] + 0.15 * relief[1][i];
                double light = (0.88 + 0.24 * blocks.light[c]) * (0.9 + 0.1 * relief[1][i])
                        * (1 + 0.07 * fine[1][i]) * (1 + 0.08 * ledge) * (1 - 0.2 * rim);
                double cr = mix(0.165, 0.195, brown) * light;
                double cg = mix(0.165, 0.16, brown) * light;
                double cb = mix(0.165, 0.13, brown) * light;
                double lichen = smoothstep(1.9, 2.5, fine[1][i] + 1.2 * low[1][i]) * (1 - crack);
                cr = mix(cr, 0.30, 0.7 * lichen);
                cg = mix(cg, 0.29, 0.7 * lichen);
                cb = mix(cb, 0.20, 0.7 * lichen);
                double darken = 1 - 0.75 * crack;
                r[i] = (float) (cr * darken);
                g[i] = (float) (cg * darken);
                b[i] = (float) (cb * darken);
                gloss[i] = (float) (0.3 + 0.05 * fine[0][i] + 0.25 * crack - 0.2 * lichen); // cracks hold water
            }
        }
        return new MaterialFields(r, g, b, height, gloss);
    }

    // ---- snow ---------------------------------------------------------------------------------------------------

    MaterialFields snow(SplittableRandom rng) {
        int nn = n * n;
        double[][] drifts = noise.pair(rng, PeriodicNoise.band(1, 40, 3.0));    // drift relief, brightness
        double[][] grain = noise.pair(rng, PeriodicNoise.band(64, 256, 0.5));   // grain relief, sparkle
        float[] r = new float[nn], g = new float[nn], b = new float[nn], height = new float[nn], gloss = new float[nn];
        for (int i = 0; i < nn; i++) {
            double hollow = 0.6 * smoothstep(0.3, -1.8, drifts[0][i]);
            double light = 0.97 + 0.03 * drifts[1][i];
            r[i] = (float) (mix(0.86, 0.70, hollow) * light);
            g[i] = (float) (mix(0.89, 0.79, hollow) * light);
            b[i] = (float) (mix(0.92, 0.93, hollow) * light);
            height[i] = (float) (SNOW_DRIFT * drifts[0][i] + 0.25 * grain[0][i]);
            // wind-glazed crust shines in patches; single crystals sparkle where the grain field peaks
            double crust = 0.2 * smoothstep(0.6, 1.6, drifts[1][i]);
            double sparkle = smoothstep(2.7, 3.1, grain[1][i]);
            gloss[i] = (float) mix(0.55 + crust + 0.05 * grain[0][i], 1.0, sparkle);
        }
        return new MaterialFields(r, g, b, height, gloss);
    }

    // ---- shared -------------------------------------------------------------------------------------------------

    /** The texel at (x, y) of the periodic tile: indices wrap. */
    private int index(int x, int y) {
        return (y & mask) * n + (x & mask);
    }

    private static double smoothstep(double edge0, double edge1, double x) {
        double t = Math.min(1, Math.max(0, (x - edge0) / (edge1 - edge0)));
        return t * t * (3 - 2 * t);
    }

    private static double mix(double a, double b, double t) {
        return a + (b - a) * t;
    }
}

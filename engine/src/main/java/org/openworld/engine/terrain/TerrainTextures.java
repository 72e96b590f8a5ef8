package org.openworld.engine.terrain;

import java.util.Arrays;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import org.jtransforms.fft.DoubleFFT_2D;

/**
 * Synthesised surface textures of the terrain's three materials, grass, rock and snow (paper 2.2): for each an
 * albedo and a detail texture, square, tileable and deterministic from a seed. No third-party art.
 *
 * <p><b>Tileable by construction.</b> Every random field is periodic over the tile: noise is shaped in the frequency
 * domain as a 1/f^β spectrum over integer frequencies and brought back with an inverse FFT
 * ({@code DoubleFFT_2D.complexInverse}; the real and imaginary parts give two independent fields for one
 * transform), the same idea as the terrain's height map; strata run along an integer number of cycles; grass blades
 * are stamped with wrapped texel indices. So the last column's right-hand neighbour is the first column, exactly as
 * for any interior pair.
 *
 * <p><b>What each material is made of</b> (relief heights in texels; the normal comes from their derivatives):
 * <ul>
 *   <li>grass: a soil layer of fine noise under thousands of stamped blades (random direction, slight curl, tapered,
 *       rising from root to tip), denser in low-frequency clumps; blade colour from dark green to yellow-green, drier
 *       (olive) in large patches, roots in shadow;</li>
 *   <li>rock: blocks from a periodic Voronoi diagram of warped coordinates, each a tilted facet chipped round at its
 *       edges, cracks between them (open in places) and finer fractures inside; rough 1/f^2.6 relief and shallow
 *       ledged strata on top; grey to brown per block and stratum, dark cracks, a little lichen; cracks hold water
 *       and shine;</li>
 *   <li>snow: soft 1/f³ drifts and a fine grain; near white, blue in the hollows (light that has travelled through
 *       snow), sparkling texels of full gloss where the grain field peaks.</li>
 * </ul>
 *
 * <p><b>Layout.</b> Both textures are RGBA8, rows from y = 0, texel (x, y) at {@code 4 (y size + x)}.
 * Albedo: sRGB-encoded colour (upload as {@code GL_SRGB8_ALPHA8} so sampling returns linear values), alpha 255.
 * Detail: r, g = the tangent-space normal's x (along +u) and y (along +v), each encoded {@code n * 0.5 + 0.5};
 * b = relief height 0..1 (material blending uses it); a = gloss 0..1 (specular power and reflection strength).
 *
 * <p>Cost: eight complex 512² inverse FFTs and a few passes over the texels, the three materials in parallel:
 * about 0.14 s on two busy cores once the JIT has compiled it, 0.5 to 0.9 s for the first call in a fresh JVM
 * (interpreted loops); run it on a worker thread at start-up and hand the result to
 * {@link TerrainMaterials#TerrainMaterials(org.openworld.engine.gl.GlContext, TerrainTextures)}.
 */
public final class TerrainTextures {

    /**
     * Texels along each side of a tile, a power of two for mipmapping and the FFT. At the default 2.7 m tile a texel
     * is 5 mm, about one pixel on the ground at a walker's feet; 1024 would quadruple the synthesis time for detail
     * only seen when crouching.
     */
    public static final int SIZE = 512;

    /** The materials, in texture-array layer order (shaders/terrain/material.glsl's MAT_GRASS, MAT_ROCK, MAT_SNOW). */
    public enum Material { GRASS, ROCK, SNOW }

    /**
     * A radial amplitude spectrum over integer frequencies (cycles per tile), given the squared frequency
     * fx² + fy²; zero outside the band it was made for, so those coefficients cost no random numbers.
     */
    @FunctionalInterface
    private interface Spectrum {
        double amplitude(double f2);
    }

    /** Linear RGB, relief height in texels (the normal's source) and gloss of one material, before encoding. */
    private record Fields(float[] red, float[] green, float[] blue, float[] height, float[] gloss) {
    }

    private final int size;
    private final Map<Material, byte[]> albedo = new EnumMap<>(Material.class);
    private final Map<Material, byte[]> detail = new EnumMap<>(Material.class);

    private TerrainTextures(int size) {
        this.size = size;
    }

    /**
     * Synthesises all three materials at {@link #SIZE}, in parallel (each from its own random stream, so the result
     * does not depend on the order they finish in); the same seed gives the same texels.
     */
    public static TerrainTextures generate(int seed) {
        TerrainTextures t = new TerrainTextures(SIZE);
        List<byte[][]> encoded = Arrays.stream(Material.values()).parallel().map(m -> {
            Synthesis s = new Synthesis(SIZE);
            SplittableRandom rng = new SplittableRandom(seed * 0x9E3779B97F4A7C15L + m.ordinal());
            Fields f = switch (m) {
                case GRASS -> s.grass(rng);
                case ROCK -> s.rock(rng);
                case SNOW -> s.snow(rng);
            };
            return new byte[][] {s.encodeAlbedo(f), s.encodeDetail(f)};
        }).toList();
        for (Material m : Material.values()) {
            t.albedo.put(m, encoded.get(m.ordinal())[0]);
            t.detail.put(m, encoded.get(m.ordinal())[1]);
        }
        return t;
    }

    /** Texels along each side. */
    public int size() {
        return size;
    }

    /** RGBA8 albedo of one material: sRGB-encoded colour, alpha 255 (a copy). */
    public byte[] albedo(Material m) {
        return albedo.get(m).clone();
    }

    /** RGBA8 detail of one material: normal x, y (encoded 0..1), relief height, gloss (a copy). */
    public byte[] detail(Material m) {
        return detail.get(m).clone();
    }

    /** The synthesis of one material's textures; holds the FFT plan and the sRGB table. */
    private static final class Synthesis {

        /** Entries of the linear-to-sRGB table: 4096 steps keep dark values (where sRGB is steep) exact to 1/255. */
        private static final int SRGB_TABLE = 4096;
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
        private final DoubleFFT_2D fft;
        private final byte[] srgb = new byte[SRGB_TABLE + 1];

        Synthesis(int n) {
            this.n = n;
            this.mask = n - 1;
            this.fft = new DoubleFFT_2D(n, n);
            for (int i = 0; i <= SRGB_TABLE; i++) {
                double c = (double) i / SRGB_TABLE;
                double e = c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055;
                srgb[i] = (byte) Math.round(e * 255);
            }
        }

        // ---- grass ----------------------------------------------------------------------------------------------

        Fields grass(SplittableRandom rng) {
            int nn = n * n;
            double[][] low = noisePair(rng, band(1.5, 10, 2.0));     // clump density, dryness
            double[][] soil = noisePair(rng, band(12, 200, 1.0));    // soil relief, soil colour
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
            return new Fields(r, g, bl, height, gloss);
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

        // ---- rock -----------------------------------------------------------------------------------------------

        Fields rock(SplittableRandom rng) {
            int nn = n * n;
            double[][] relief = noisePair(rng, band(2, 160, 2.6));   // rough relief, colour variation
            double[][] fine = noisePair(rng, band(40, 256, 1.0));    // grain, lichen
            double[][] warp = noisePair(rng, band(2, 10, 2.0));      // bends the cracks (x and y displacement)
            double[][] low = noisePair(rng, band(1, 4, 2.0));        // strata warp, where cracks are open
            Cells blocks = new Cells(rng, ROCK_BLOCKS);
            Cells fractures = new Cells(rng, ROCK_FRACTURES);
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
            return new Fields(r, g, b, height, gloss);
        }

        /**
         * Jittered points on a periodic grid of {@code count}² cells, with per-cell facet parameters: the Voronoi
         * diagram of a tileable point set, found by looking at the 3 × 3 cells around a texel with wrapped indices.
         */
        private final class Cells {
            final int count;
            final double[] px, py, base, slopeX, slopeY, tone, light;
            /** After {@link #nearest}: offset of the texel from the nearest point, and the two nearest distances. */
            double dx, dy, d1, d2;
            private double n1x, n1y, n2x, n2y;

            Cells(SplittableRandom rng, int count) {
                this.count = count;
                int cells = count * count;
                px = new double[cells];
                py = new double[cells];
                base = new double[cells];
                slopeX = new double[cells];
                slopeY = new double[cells];
                tone = new double[cells];
                light = new double[cells];
                double size = (double) n / count;
                for (int k = 0; k < cells; k++) {
                    px[k] = (k % count + 0.15 + 0.7 * rng.nextDouble()) * size;
                    py[k] = (k / count + 0.15 + 0.7 * rng.nextDouble()) * size;
                    base[k] = (rng.nextDouble() - 0.5) * 0.3 * size;        // texels: blocks stand proud or sunk
                    double angle = rng.nextDouble() * 2 * Math.PI;
                    double tilt = 0.12 + 0.3 * rng.nextDouble();            // 7 to 23 degrees
                    slopeX[k] = tilt * Math.cos(angle);
                    slopeY[k] = tilt * Math.sin(angle);
                    tone[k] = rng.nextDouble();
                    light[k] = rng.nextDouble();
                }
            }

            /** The cell whose point is nearest to (x, y), in the periodic tile; sets dx, dy, d1, d2. */
            int nearest(double x, double y) {
                double size = (double) n / count;
                int cx = (int) Math.floor(x / size);
                int cy = (int) Math.floor(y / size);
                d1 = Double.MAX_VALUE;
                d2 = Double.MAX_VALUE;
                int best = 0;
                for (int j = -1; j <= 1; j++) {
                    for (int i = -1; i <= 1; i++) {
                        int gx = cx + i;
                        int gy = cy + j;
                        int k = Math.floorMod(gy, count) * count + Math.floorMod(gx, count);
                        // the point's copy next to this texel: shift by whole tiles where the index wrapped
                        double ox = x - (px[k] + Math.floorDiv(gx, count) * (double) n);
                        double oy = y - (py[k] + Math.floorDiv(gy, count) * (double) n);
                        double d = ox * ox + oy * oy;     // squared until the two nearest are known
                        if (d < d1) {
                            d2 = d1;
                            n2x = n1x;
                            n2y = n1y;
                            d1 = d;
                            n1x = ox;
                            n1y = oy;
                            best = k;
                        } else if (d < d2) {
                            d2 = d;
                            n2x = ox;
                            n2y = oy;
                        }
                    }
                }
                d1 = Math.sqrt(d1);
                d2 = Math.sqrt(d2);
                dx = n1x;
                dy = n1y;
                return best;
            }

            /**
             * Distance to the bisector between the nearest and the second-nearest point, texels: the true distance
             * to the cell's edge there (d2 − d1 would overstate it away from the line joining the points).
             */
            double edgeDistance() {
                // texel offset from points A (nearest) and B: p − A = n1, p − B = n2; B − A = n1 − n2
                double abx = n1x - n2x;
                double aby = n1y - n2y;
                double len = Math.hypot(abx, aby);
                // signed distance of p from the bisector plane, measured towards A: (|p−B|² − |p−A|²) / (2 |B−A|)
                return (d2 * d2 - d1 * d1) / (2 * len);
            }
        }

        // ---- snow -----------------------------------------------------------------------------------------------

        Fields snow(SplittableRandom rng) {
            int nn = n * n;
            double[][] drifts = noisePair(rng, band(1, 40, 3.0));    // drift relief, brightness
            double[][] grain = noisePair(rng, band(64, 256, 0.5));   // grain relief, sparkle
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
            return new Fields(r, g, b, height, gloss);
        }

        // ---- shared ---------------------------------------------------------------------------------------------

        /**
         * Two independent periodic Gaussian fields with the given amplitude spectrum, each of zero mean and unit
         * variance. Complex coefficients with independent Gaussian parts make the inverse transform's real and
         * imaginary parts two independent real fields of the same spectrum.
         */
        double[][] noisePair(SplittableRandom rng, Spectrum spectrum) {
            double[] a = new double[2 * n * n];
            for (int ky = 0; ky < n; ky++) {
                int fy = ky <= n / 2 ? ky : ky - n;
                for (int kx = 0; kx < n; kx++) {
                    int fx = kx <= n / 2 ? kx : kx - n;
                    double amplitude = fx == 0 && fy == 0 ? 0 : spectrum.amplitude(fx * fx + fy * fy);
                    if (amplitude > 1e-9) {
                        int i = 2 * (ky * n + kx);
                        a[i] = amplitude * rng.nextGaussian();
                        a[i + 1] = amplitude * rng.nextGaussian();
                    }
                }
            }
            fft.complexInverse(a, false);
            double[] re = new double[n * n];
            double[] im = new double[n * n];
            for (int i = 0; i < n * n; i++) {
                re[i] = a[2 * i];
                im[i] = a[2 * i + 1];
            }
            return new double[][] {standardise(re), standardise(im)};
        }

        /**
         * 1/f^β power (amplitude f^(−β/2)) between soft edges at {@code low} and {@code high} cycles per tile:
         * β = 0 is white noise in the band, 2 the rough relief of rock, 3 the smooth swell of snow drifts.
         */
        static Spectrum band(double low, double high, double beta) {
            double low2 = low * low;
            double high2 = high * high;
            return f2 -> {
                double below = low2 / f2;
                double above = f2 / high2;
                double exponent = below * below + above * above;
                // beyond exp(−20) = 2e−9 of the peak: nothing visible at 8 bits
                return exponent > 20 ? 0 : Math.exp(-exponent - beta / 4 * Math.log(f2));
            };
        }

        private static double[] standardise(double[] v) {
            double mean = 0;
            for (double x : v) {
                mean += x;
            }
            mean /= v.length;
            double var = 0;
            for (double x : v) {
                var += (x - mean) * (x - mean);
            }
            double scale = 1 / Math.sqrt(var / v.length);
            for (int i = 0; i < v.length; i++) {
                v[i] = (v[i] - mean) * scale;
            }
            return v;
        }

        private int index(int x, int y) {
            return (y & mask) * n + (x & mask);
        }

        byte[] encodeAlbedo(Fields f) {
            byte[] out = new byte[n * n * 4];
            for (int i = 0; i < n * n; i++) {
                out[4 * i] = toSrgb(f.red()[i]);
                out[4 * i + 1] = toSrgb(f.green()[i]);
                out[4 * i + 2] = toSrgb(f.blue()[i]);
                out[4 * i + 3] = (byte) 255;
            }
            return out;
        }

        /**
         * Normal from the wrapped central differences of the relief; the relief itself stored as mean ± 2.5 standard
         * deviations over 0..1, so every material's height spreads alike for the blending in the shader.
         */
        byte[] encodeDetail(Fields f) {
            float[] h = f.height();
            double mean = 0;
            for (float v : h) {
                mean += v;
            }
            mean /= h.length;
            double var = 0;
            for (float v : h) {
                var += (v - mean) * (v - mean);
            }
            double spread = 5 * Math.sqrt(var / h.length);
            byte[] out = new byte[n * n * 4];
            for (int y = 0; y < n; y++) {
                for (int x = 0; x < n; x++) {
                    int i = y * n + x;
                    double dx = (h[index(x + 1, y)] - h[index(x - 1, y)]) * 0.5;
                    double dy = (h[index(x, y + 1)] - h[index(x, y - 1)]) * 0.5;
                    double len = Math.sqrt(dx * dx + dy * dy + 1);
                    out[4 * i] = unorm(-dx / len * 0.5 + 0.5);
                    out[4 * i + 1] = unorm(-dy / len * 0.5 + 0.5);
                    out[4 * i + 2] = unorm(0.5 + (h[i] - mean) / spread);
                    out[4 * i + 3] = unorm(f.gloss()[i]);
                }
            }
            return out;
        }

        private byte toSrgb(float linear) {
            return srgb[(int) (Math.min(Math.max(linear, 0f), 1f) * SRGB_TABLE + 0.5f)];
        }

        private static byte unorm(double v) {
            return (byte) Math.round(Math.min(Math.max(v, 0), 1) * 255);
        }

        private static double smoothstep(double edge0, double edge1, double x) {
            double t = Math.min(1, Math.max(0, (x - edge0) / (edge1 - edge0)));
            return t * t * (3 - 2 * t);
        }

        private static double mix(double a, double b, double t) {
            return a + (b - a) * t;
        }
    }
}

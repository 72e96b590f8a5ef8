package org.openworld.engine.vegetation;

import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.IntStream;
import org.openworld.engine.texture.MaterialEncoding;
import org.openworld.engine.texture.MaterialFields;
import org.openworld.engine.texture.PeriodicNoise;

/**
 * The plants' bark, synthesised at start as the ground's materials are (the terrain's {@link PeriodicNoise} shaped
 * into a {@link MaterialFields} and packed by {@link MaterialEncoding}: an sRGB albedo and a detail texture of
 * tangent-space normal, relief and gloss), one square tileable layer per bark:
 *
 * <ul>
 *   <li>{@link #CONIFER}: a spruce's or pine's, furrowed into scaly plates that run up the stem: dark furrows
 *       {@value #FURROW_DEPTH} texels deep between grey-brown plates;</li>
 *   <li>{@link #BROADLEAF} (trees and bushes): a beech's, smooth and grey, shallow swells and paler patches.</li>
 * </ul>
 *
 * <p><b>Streaks up the stem from isotropic noise.</b> The noise's spectrum is radial, every direction alike. Reading
 * a periodic field at {@code (k x mod n, y)} with a whole {@code k} squeezes it k times across and keeps it periodic
 * over the tile: its features become k times taller than wide. The conifer's plates take k = {@value #CONIFER_STRETCH},
 * the broadleaf's swells {@value #BROADLEAF_STRETCH}.
 *
 * <p><b>Data path.</b> {@link #generate} (any thread) → {@link PlantMaps} (GL: two mipmapped texture arrays, layer
 * = the bark) → {@code shaders/vegetation/surface.glsl}, which wraps a layer {@code BARK_AROUND} times round the trunk
 * and a tile every {@code BARK_TILE_M} up it, for the meshes and the impostors' bake alike.
 *
 * <p><b>Cost.</b> Two noise pairs per bark at {@value #SIZE}² (two complex 256² inverse FFTs) and one pass per
 * texture: 80-380 ms at start on two cores under load 21 once compiled, 1.2 s in a fresh JVM (a tenth to a twentieth
 * of the terrain's textures in the same sitting); 2 · 2 · 256² · 4 B = 1 MiB of textures, 1.33 MiB with their
 * mipmaps.
 *
 * <p><b>Limits.</b> A height field: no peeling bark, no moss on the shaded side; the colours are hand-tuned
 * reflectances (bark reflects 5-20 % of visible light), not measured ones.
 */
final class BarkTextures {

    /** Texels per side: at one tile per metre up the stem, 4 mm a texel, a pixel at 2 m from the eye at 1080p. */
    static final int SIZE = 256;
    /** The layers. */
    static final int CONIFER = 0;
    static final int BROADLEAF = 1;
    static final int LAYERS = 2;
    /** Depth of the conifer's furrows between its plates, texels (1.5 cm at 4 mm a texel). */
    static final double FURROW_DEPTH = 4;
    /** Relief of the broadleaf's smooth swells, texels per standard deviation (a few millimetres). */
    static final double SWELL_DEPTH = 0.8;
    /** How many times taller than wide the conifer's plates are, and the broadleaf's swells (a whole number). */
    static final int CONIFER_STRETCH = 4;
    static final int BROADLEAF_STRETCH = 2;

    private final List<byte[]> albedo;
    private final List<byte[]> detail;

    private BarkTextures(List<byte[]> albedo, List<byte[]> detail) {
        this.albedo = albedo;
        this.detail = detail;
    }

    /** Both barks, in parallel, each from its own stream of {@code seed}: the same seed gives the same texels. */
    static BarkTextures generate(long seed) {
        MaterialEncoding encoding = new MaterialEncoding(SIZE);
        List<MaterialFields> fields = IntStream.range(0, LAYERS).parallel().mapToObj(layer -> {
            SplittableRandom rng = new SplittableRandom(seed * 0x9E3779B97F4A7C15L + layer);
            return layer == CONIFER ? conifer(rng) : broadleaf(rng);
        }).toList();
        return new BarkTextures(fields.stream().map(encoding::albedo).toList(),
                fields.stream().map(encoding::detail).toList());
    }

    /** RGBA8 albedo layers, sRGB-encoded, alpha 255 (upload as sRGB). */
    List<byte[]> albedo() {
        return albedo;
    }

    /** RGBA8 detail layers: normal x (across the stem), y (up it), relief, gloss ({@link MaterialEncoding}). */
    List<byte[]> detail() {
        return detail;
    }

    /** Plates between furrows, stretched up the stem; grey-brown, dark in the furrows, a browner cast per plate. */
    static MaterialFields conifer(SplittableRandom rng) {
        PeriodicNoise noise = new PeriodicNoise(SIZE);
        double[][] plates = noise.pair(rng, PeriodicNoise.band(3, 16, 2.0));  // plates and furrows, plate tone
        double[][] fine = noise.pair(rng, PeriodicNoise.band(30, 128, 1.0)); // scales on the plates, grain
        double[] plate = stretched(plates[0], CONIFER_STRETCH);
        double[] tone = stretched(plates[1], CONIFER_STRETCH);
        return fields((i, out) -> {
            double top = smoothstep(-0.7, 0.3, plate[i]); // 0 in a furrow, 1 on a plate
            double light = (0.55 + 0.45 * top) * (1 + 0.08 * fine[1][i]);
            double brown = 0.5 + 0.25 * tone[i];
            out[0] = mix(0.10, 0.13, brown) * light;
            out[1] = mix(0.085, 0.08, brown) * light;
            out[2] = mix(0.07, 0.05, brown) * light;
            out[3] = FURROW_DEPTH * top + 0.35 * fine[0][i];
            out[4] = 0.1 + 0.05 * top;
        });
    }

    /** Smooth grey bark, shallow swells stretched up the stem, paler patches. */
    static MaterialFields broadleaf(SplittableRandom rng) {
        PeriodicNoise noise = new PeriodicNoise(SIZE);
        double[][] swells = noise.pair(rng, PeriodicNoise.band(2, 40, 2.5)); // swells, patches
        double[][] fine = noise.pair(rng, PeriodicNoise.band(40, 128, 1.0)); // grain
        double[] swell = stretched(swells[0], BROADLEAF_STRETCH);
        double[] patch = stretched(swells[1], BROADLEAF_STRETCH);
        return fields((i, out) -> {
            double pale = smoothstep(0.2, 1.5, patch[i]);
            double light = (0.9 + 0.06 * swell[i]) * (1 + 0.05 * fine[1][i]);
            out[0] = mix(0.11, 0.16, pale) * light;
            out[1] = mix(0.095, 0.15, pale) * light;
            out[2] = mix(0.075, 0.12, pale) * light;
            out[3] = SWELL_DEPTH * swell[i] + 0.2 * fine[0][i];
            out[4] = 0.15;
        });
    }

    /** Texel i's red, green, blue, relief (texels) and gloss, into out. */
    private interface Texel {
        void make(int i, double[] out);
    }

    private static MaterialFields fields(Texel texel) {
        int nn = SIZE * SIZE;
        float[] r = new float[nn], g = new float[nn], b = new float[nn], height = new float[nn], gloss = new float[nn];
        double[] out = new double[5];
        for (int i = 0; i < nn; i++) {
            texel.make(i, out);
            r[i] = (float) out[0];
            g[i] = (float) out[1];
            b[i] = (float) out[2];
            height[i] = (float) out[3];
            gloss[i] = (float) out[4];
        }
        return new MaterialFields(r, g, b, height, gloss);
    }

    /** The periodic field read at (k x mod n, y): k times narrower across, still periodic (the class comment). */
    static double[] stretched(double[] field, int k) {
        double[] out = new double[field.length];
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                out[y * SIZE + x] = field[y * SIZE + (k * x) % SIZE];
            }
        }
        return out;
    }

    private static double smoothstep(double edge0, double edge1, double x) {
        double t = Math.min(1, Math.max(0, (x - edge0) / (edge1 - edge0)));
        return t * t * (3 - 2 * t);
    }

    private static double mix(double a, double b, double t) {
        return a + (b - a) * t;
    }
}

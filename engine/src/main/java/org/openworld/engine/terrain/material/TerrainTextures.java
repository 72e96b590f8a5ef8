package org.openworld.engine.terrain.material;

import java.util.Arrays;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import org.openworld.engine.texture.MaterialEncoding;
import org.openworld.engine.texture.MaterialFields;
import org.openworld.engine.texture.PeriodicNoise;

/**
 * Synthesised surface textures of the terrain's three materials, grass, rock and snow (paper 2.2): for each an
 * albedo and a detail texture, square, tileable and deterministic from a seed. No third-party art.
 *
 * <p><b>How.</b> Per material, three steps, each its own class:
 * <ol>
 *   <li>{@link PeriodicNoise}: Gaussian fields shaped in the frequency domain as 1/f^β spectra over integer
 *       frequencies and brought back by an inverse FFT, periodic over the tile (the terrain's height map uses the
 *       same idea);</li>
 *   <li>{@link MaterialRecipes}: what each material is made of, from those fields, {@link PeriodicCells} (the rock's
 *       blocks) and stamped blades of grass, as linear colour, relief and gloss ({@link MaterialFields});</li>
 *   <li>{@link MaterialEncoding}: packed into RGBA8 for the GPU.</li>
 * </ol>
 * Every ingredient is periodic, so the last column's right-hand neighbour is the first column, exactly as for any
 * interior pair.
 *
 * <p><b>Layout.</b> Both textures are RGBA8, rows from y = 0, texel (x, y) at {@code 4 (y size + x)}.
 * Albedo: sRGB-encoded colour (upload as {@code GL_SRGB8_ALPHA8} so sampling returns linear values), alpha 255.
 * Detail: r, g = the tangent-space normal's x (along +u) and y (along +v), each encoded {@code n * 0.5 + 0.5};
 * b = relief height 0..1 (material blending uses it); a = gloss 0..1 (specular power and reflection strength).
 *
 * <p><b>Cost.</b> Eight complex 512² inverse FFTs and a few passes over the texels, the three materials in parallel
 * (their FFTs take turns under {@link org.openworld.engine.core.FftThreads}' lock): about 0.14 s on two busy cores
 * once the JIT has compiled it, 0.5 to 0.9 s for the first call in a fresh JVM (interpreted loops); run it on a
 * worker thread at start-up and hand the result to
 * {@link TerrainMaterials#TerrainMaterials(org.openworld.engine.gl.GlContext, TerrainTextures)}.
 *
 * <p><b>Limits.</b> One tile per material, repeated: the terrain shader samples it at two scales to hide that, and
 * {@link #quilted} cuts 16 Wang tiles from it for {@code materials.tiling=quilted}, laid aperiodically. A
 * texel is 5 mm at the default tile, so nothing larger than the tile's 2.7 m (a boulder field, a snow cornice) is in
 * the textures; the terrain's own relief and snow map carry those.
 */
public final class TerrainTextures {

    /**
     * Texels along each side of a tile, a power of two for mipmapping and the FFT. At the default 2.7 m tile a texel
     * is 5 mm, about one pixel on the ground at a walker's feet; 1024 would quadruple the synthesis time for detail
     * only seen when crouching.
     */
    public static final int SIZE = 512;

    /** The materials, in texture-array layer order (terrain/material/material.glsl's MAT_GRASS, MAT_ROCK, MAT_SNOW). */
    public enum Material { GRASS, ROCK, SNOW }

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
        MaterialEncoding encoding = new MaterialEncoding(SIZE);
        List<byte[][]> encoded = Arrays.stream(Material.values()).parallel().map(m -> {
            SplittableRandom rng = new SplittableRandom(seed * 0x9E3779B97F4A7C15L + m.ordinal());
            MaterialFields f = new MaterialRecipes(SIZE).make(m, rng);
            return new byte[][] {encoding.albedo(f), encoding.detail(f)};
        }).toList();
        for (Material m : Material.values()) {
            t.albedo.put(m, encoded.get(m.ordinal())[0]);
            t.detail.put(m, encoded.get(m.ordinal())[1]);
        }
        return t;
    }

    /**
     * The three materials as {@link WangTiles quilted Wang tiles}: each an atlas of 16 tiles
     * {@link WangTiles#ATLAS} tiles wide, cut from its tile (each from its own random stream of {@code seed}, in
     * parallel); the same seed gives the same texels.
     */
    public TerrainTextures quilted(int seed) {
        TerrainTextures t = new TerrainTextures(WangTiles.ATLAS * size);
        List<WangTiles.Atlas> atlases = Arrays.stream(Material.values()).parallel().map(m -> WangTiles.build(
                albedo.get(m), detail.get(m), size, new SplittableRandom(seed * 0x632BE59BD9B4E019L + m.ordinal())))
                .toList();
        for (Material m : Material.values()) {
            t.albedo.put(m, atlases.get(m.ordinal()).albedo());
            t.detail.put(m, atlases.get(m.ordinal()).detail());
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
}

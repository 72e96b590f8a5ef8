package org.openworld.engine.terrain.material;

import java.util.List;
import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Settings of the terrain materials (paper 2.2, figures 1 and 3), keys {@code materials.*}: where snow lies, and
 * which per-texel details shade the surface. They are read every frame by {@link TerrainMaterials#bind}, so
 * toggling one costs nothing and reallocates nothing.
 *
 * @param snowMode    where snow lies: from the snow map (figure 1b) or above a fixed height (figure 1a)
 * @param normalMap   perturb the normal with the materials' tangent-space normal maps (figure 3, "normal")
 * @param glossMap    add sun highlights and a sky reflection, scaled per texel by the gloss maps (figure 3, "gloss")
 * @param skyOcclusion let the relief hide its share of the sky's light ({@link HorizonSearch}): in valleys and at the
 *                    feet of cliffs that share is lit by the terrain instead, warmer, and darker under a low sun
 * @param detailScale side of the fine texture tile (the synthesised exemplar) on the ground; the coarse tile that is
 *                    blended in to hide the repetition is {@code shaders/terrain/material/material.glsl}'s
 *                    {@code MAT_COARSE_FACTOR} times larger; each quilted Wang tile is one such tile
 * @param farTexels   distance from the eye beyond which the terrain reads the {@link FarMaterial} baked once instead
 *                    of every material layer, in texels of that material (2 m each on the default map, 1 m on a
 *                    1 km one), so a coarser bake starts further out; the near material fades into it over the last
 *                    {@link FarMaterial#BLEND_FRACTION} of that distance. The unbounded world bakes none: beyond
 *                    that many of its level-0 samples its far program reads the coarse tile alone
 *                    ({@link org.openworld.engine.terrain.TerrainShading})
 * @param tiling      how the detail textures cover the ground: repeated tiles, 16 Wang tiles quilted from them at
 *                    start-up (Cohen et al. 2003), laid aperiodically by a hash at one lookup per scale, or
 *                    stochastic tiling (Heitz and Neyret 2018), which hides the repetition at three times the texture
 *                    lookups of the near material
 * @param cliffs      how rock is projected on steep slopes in the near material: from above only, or from above and
 *                    along X and Z, blended by the normal (triplanar), so cliffs are not stretched; read when the
 *                    world is built, since the near programs are compiled with it
 * @param specularAa  specular anti-aliasing: each pixel's highlight widened by how much the lit normal turns across
 *                    the pixel (Toksvig's lobe, the spread measured in screen space), so far bumps give a steady sheen
 *                    instead of glints that come and go with every step of the camera
 */
public record MaterialSettings(
        @Setting(doc = "where snow lies: snow-map (probabilistic map) or altitude-bands (plain height bands)")
        SnowMode snowMode,
        @Setting(doc = "tangent-space normal maps on the materials") boolean normalMap,
        @Setting(doc = "gloss maps: sun highlights and sky reflection") boolean glossMap,
        @Setting(doc = "the relief hides its share of the sky's light (horizon occlusion)") boolean skyOcclusion,
        @Setting(doc = "side of the fine material texture tile", unit = "m", min = 0.25, max = 50) double detailScale,
        @Setting(doc = "distance beyond which the terrain runs the far material, in its texels (the unbounded "
                + "world's: level-0 samples)", min = 0,
                max = 100000) double farTexels,
        @Setting(doc = "how the detail textures tile: repeat, quilted (Wang tiles) or stochastic (Heitz-Neyret)")
        Tiling tiling,
        @Setting(doc = "rock on steep slopes: planar (from above, stretched) or triplanar (blended by the normal)",
                atStart = true) Cliffs cliffs,
        @Setting(doc = "specular anti-aliasing: highlights widened by the normal's spread over the pixel")
        boolean specularAa) {

    /** How snow is placed on the terrain. */
    public enum SnowMode {
        /** Snow where the terrain's snow map has it: drawn with probability rising with height, then smoothed. */
        SNOW_MAP,
        /** Snow above a fixed normalised height: the flat, unrealistic band of the paper's figure 1a. */
        ALTITUDE_BANDS
    }

    /**
     * How the detail textures cover the ground; each tiling is a variant of the near terrain and the bake programs
     * ({@code MAT_WANG} and {@code MAT_STOCHASTIC} in {@code shaders/terrain/material/material.glsl}), so none pays for
     * another.
     */
    public enum Tiling {
        /** The tiles repeat: one lookup per scale, visibly periodic from tens of metres up. */
        REPEAT,
        /**
         * Quilted Wang tiles (Cohen, Shade, Hiller and Deussen 2003), made at start-up: 16 tiles cut from each
         * material's tile along minimum-error seams ({@link WangTiles}), laid by a hash of the tile grid so that
         * touching edges match and no grid repeats; one lookup per scale, 16 times the texture memory.
         */
        QUILTED,
        /**
         * Histogram-preserving stochastic tiling (Heitz and Neyret 2018), with the mean-and-variance-preserving
         * blend: three randomly shifted lookups per scale, blended over a triangle grid; nothing repeats.
         */
        STOCHASTIC;

        /** The shader defines of the programs for this tiling. */
        public List<String> defines() {
            return switch (this) {
                case REPEAT -> List.of();
                case QUILTED -> List.of("MAT_WANG");
                case STOCHASTIC -> List.of("MAT_STOCHASTIC");
            };
        }

        /** What this tiling's programs add to their GL labels: nothing for the repeated tiles. */
        public String roleSuffix() {
            return this == REPEAT ? "" : "." + name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    /** How the near material projects the rock onto the ground ({@code MAT_TRIPLANAR} in material.glsl). */
    public enum Cliffs {
        /** From above only: a face of slope a shows the texture stretched by 1 / cos a down its fall line. */
        PLANAR,
        /** From above and along X and Z, blended by the normal: twice the rock's lookups, no stretch. */
        TRIPLANAR;

        /** The near programs' shader defines for this projection. */
        public List<String> defines() {
            return this == TRIPLANAR ? List.of("MAT_TRIPLANAR") : List.of();
        }
    }

    public static final MaterialSettings DEFAULTS = new MaterialSettings(
            SnowMode.SNOW_MAP,
            true,
            true,
            true,
            2.7,    // m: 512 texels over 2.7 m is 5 mm per texel, about one pixel on the ground at a walker's feet
            150,    // texels (300 m on the default map): nearer, a baked texel spans several pixels of a 720-row view
                    // and the ground looks blurred; 75 (150 m) already shows it on figure 3's mountainside
            Tiling.REPEAT,
            Cliffs.PLANAR, // triplanar costs about a tenth of the frame on valley.path (docs/terrain.md)
            true);

    public static final SettingsGroup<MaterialSettings> SETTINGS =
            SettingsGroup.of("materials", MaterialSettings.class, DEFAULTS);
}

package org.openworld.engine.terrain.material;

import java.util.List;
import org.openworld.engine.core.Owned;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Labelled;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.TextureArray;
import org.openworld.engine.gl.Uniform;
import org.openworld.engine.origin.MaterialOrigin;
import org.openworld.engine.terrain.material.TerrainTextures.Material;

/**
 * The GPU side of the terrain materials (paper 2.2): the synthesised {@link TerrainTextures} as two mipmapped
 * texture arrays (albedo, detail; one layer per {@link Material}), plus the binding of
 * {@code shaders/terrain/material/material.glsl}'s samplers and settings. Glossy surfaces reflect the sky's
 * environment map, which the engine binds for every shader ({@code shaders/common/environment.glsl}).
 *
 * <p>Use: once per program, {@code Uniforms u = TerrainMaterials.uniforms(program)}; per draw,
 * {@code materials.bind(u, settings, firstUnit)}, which takes texture units {@code firstUnit} to
 * {@code firstUnit + UNITS - 1}. A program that uses only part of material.glsl resolves only that part: the far
 * terrain lights a baked material ({@link #lightUniforms}), the bake makes it without light ({@link #layerUniforms}).
 */
public final class TerrainMaterials implements Labelled {

    /** Texture units taken from {@code firstUnit}: albedo array, detail array. */
    public static final int UNITS = 2;

    private final Owned arrays = new Owned();
    private final TextureArray albedo;
    private final TextureArray detail;

    /**
     * Uploads textures synthesised beforehand, e.g. on a worker thread: the tiles, or the atlas of Wang tiles cut
     * from them ({@link TerrainTextures#quilted}), whose cells are each one tile's ground wide.
     */
    public TerrainMaterials(GlContext gl, TerrainTextures textures) {
        int n = textures.size();
        List<Material> layers = List.of(Material.values());
        try {
            albedo = arrays.own(TextureArray.repeatingMipmapped(gl, n, n, Format.SRGB8_ALPHA8,
                    layers.stream().map(textures::albedo).toList()));
            detail = arrays.own(TextureArray.repeatingMipmapped(gl, n, n, Format.RGBA8,
                    layers.stream().map(textures::detail).toList()));
        } catch (RuntimeException e) {
            arrays.close();
            throw e;
        }
    }

    /** material.glsl's uniforms in one program, resolved once (the program must include material.glsl and use it). */
    public static Uniforms uniforms(ShaderProgram program) {
        return new Uniforms(program, true, true);
    }

    /** The uniforms of a program that calls {@code lightTerrain} only: the normal and gloss map switches. */
    public static Uniforms lightUniforms(ShaderProgram program) {
        return new Uniforms(program, false, true);
    }

    /** The uniforms of a program that calls {@code terrainMaterial} only: the textures, their scale and the snow. */
    public static Uniforms layerUniforms(ShaderProgram program) {
        return new Uniforms(program, true, false);
    }

    /**
     * Uses the program, binds the textures to units {@code firstUnit} .. {@code firstUnit + UNITS - 1} and sets the
     * settings' uniforms. Cheap: nothing is allocated, so settings may change every frame.
     */
    public void bind(Uniforms u, MaterialSettings settings, int firstUnit) {
        bind(u, settings, firstUnit, 0, 0);
    }

    /** The same with the render origin at (originX, 0, originZ), metres: its place on the lattices and tiles. */
    public void bind(Uniforms u, MaterialSettings settings, int firstUnit, double originX, double originZ) {
        u.program.use();
        if (u.layers) {
            albedo.bind(firstUnit);
            detail.bind(firstUnit + 1);
            u.albedo.set(firstUnit);
            u.detail.set(firstUnit + 1);
            u.detailScale.set((float) (settings.detailScale()));
            u.macroOrigin.setArray(MaterialOrigin.macro(originX, originZ));
            u.tileOrigin.setArray(MaterialOrigin.tiles(originX, originZ, settings.detailScale()));
            u.snowMode.set(switch (settings.snowMode()) { // material.glsl's MAT_SNOW_MAP and MAT_ALTITUDE_BANDS
                case SNOW_MAP -> 0;
                case ALTITUDE_BANDS -> 1;
            });
            u.snowBand.set((float) (SnowLines.BAND_LINE - SnowLines.BAND_EDGE),
                    (float) (SnowLines.BAND_LINE + SnowLines.BAND_EDGE));
        }
        if (u.light) {
            u.normalMap.set(settings.normalMap() ? 1 : 0);
            u.glossMap.set(settings.glossMap() ? 1 : 0);
            u.skyOcclusion.set(settings.skyOcclusion() ? 1 : 0);
            u.specularAa.set(settings.specularAa() ? 1 : 0);
        }
    }

    /** Names the arrays {@code name.albedo} and {@code name.detail}. */
    @Override
    public void label(String name) {
        albedo.label(name + ".albedo");
        detail.label(name + ".detail");
    }

    @Override
    public void close() {
        arrays.close();
    }

    /**
     * The resolved uniform handles of material.glsl in one program: those of the layers (textures, scale, snow) and
     * of the light (normal map, gloss map, sky occlusion and specular anti-aliasing switches), or of one of the two; the other part's handles are null.
     */
    public static final class Uniforms {
        private final ShaderProgram program;
        private final boolean layers;
        private final boolean light;
        private final Uniform.Int albedo;
        private final Uniform.Int detail;
        private final Uniform.Float detailScale;
        private final Uniform.Vec4 macroOrigin;
        private final Uniform.Vec4 tileOrigin;
        private final Uniform.Int snowMode;
        private final Uniform.Vec2 snowBand;
        private final Uniform.Int normalMap;
        private final Uniform.Int glossMap;
        private final Uniform.Float skyOcclusion;
        private final Uniform.Float specularAa;

        private Uniforms(ShaderProgram program, boolean layers, boolean light) {
            this.program = program;
            this.layers = layers;
            this.light = light;
            albedo = layers ? program.int1("uMatAlbedo") : null;
            detail = layers ? program.int1("uMatDetail") : null;
            detailScale = layers ? program.float1("uMatDetailScale") : null;
            macroOrigin = layers ? program.vec4("uMatMacroOrigin") : null;
            tileOrigin = layers ? program.vec4("uMatTileOrigin") : null;
            snowMode = layers ? program.int1("uMatSnowMode") : null;
            snowBand = layers ? program.vec2("uMatSnowBand") : null;
            normalMap = light ? program.int1("uMatNormalMap") : null;
            glossMap = light ? program.int1("uMatGlossMap") : null;
            skyOcclusion = light ? program.float1("uMatSkyOcclusion") : null;
            specularAa = light ? program.float1("uMatSpecularAa") : null;
        }
    }
}

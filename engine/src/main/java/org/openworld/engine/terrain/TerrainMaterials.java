package org.openworld.engine.terrain;

import java.util.List;
import org.joml.Vector3f;
import org.joml.Vector3fc;
import org.openworld.engine.gl.CubeMapTexture;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Texture2D;
import org.openworld.engine.gl.TextureArray;
import org.openworld.engine.gl.Uniform;
import org.openworld.engine.terrain.TerrainTextures.Material;

/**
 * The GPU side of the terrain materials (paper 2.2): the synthesised {@link TerrainTextures} as two mipmapped
 * texture arrays (albedo, detail; one layer per {@link Material}) and a gradient sky cube map for the glossy
 * reflection, plus the binding of {@code shaders/terrain/material.glsl}'s samplers and settings.
 *
 * <p>Use: once per program, {@code Uniforms u = TerrainMaterials.uniforms(program)}; per draw,
 * {@code materials.bind(u, settings, firstUnit)}, which takes texture units {@code firstUnit} to
 * {@code firstUnit + UNITS - 1}.
 *
 * <p>The sky cube map stands in until a sky system renders one: horizon haze rising to zenith blue above, a dark
 * ground below, stored for the daylight model's full-day ambient light; material.glsl scales it by the luminance of
 * {@code frame.ambientColor}, so it darkens with the day.
 */
public final class TerrainMaterials implements AutoCloseable {

    /** Texture units taken from {@code firstUnit}: albedo array, detail array, sky cube map. */
    public static final int UNITS = 3;
    /**
     * Texels along a sky cube face: a smooth gradient needs few; 64 keeps the horizon's turn (over about 5°) two
     * texels wide, and its mipmaps give the blurred sky that rough surfaces reflect.
     */
    public static final int SKY_SIZE = 64;

    /** Sky colours, linear RGB, for the daylight model's full-day ambient light (0.30, 0.38, 0.50). */
    static final Vector3fc ZENITH = new Vector3f(0.10f, 0.25f, 0.60f);
    static final Vector3fc HORIZON = new Vector3f(0.56f, 0.63f, 0.72f);
    static final Vector3fc GROUND = new Vector3f(0.09f, 0.085f, 0.07f);

    private final TextureArray albedo;
    private final TextureArray detail;
    private final CubeMapTexture sky;

    /** Synthesises the textures from {@code seed} (a fraction of a second, see {@link TerrainTextures}), uploads them. */
    public TerrainMaterials(GlContext gl, int seed) {
        this(gl, TerrainTextures.generate(seed));
    }

    /** Uploads textures synthesised beforehand, e.g. on a worker thread. */
    public TerrainMaterials(GlContext gl, TerrainTextures textures) {
        int n = textures.size();
        List<Material> layers = List.of(Material.values());
        albedo = TextureArray.repeatingMipmapped(gl, n, n, TextureArray.SRGB8_ALPHA8,
                layers.stream().map(textures::albedo).toList());
        TextureArray detailArray = null;
        try {
            detailArray = TextureArray.repeatingMipmapped(gl, n, n, Texture2D.Format.RGBA8,
                    layers.stream().map(textures::detail).toList());
            sky = CubeMapTexture.fromDirections(gl, SKY_SIZE, TerrainMaterials::skyGradient);
        } catch (RuntimeException e) {
            if (detailArray != null) {
                detailArray.close();
            }
            albedo.close();
            throw e;
        }
        detail = detailArray;
    }

    /**
     * The stand-in sky, linear RGB: horizon haze rising to zenith blue with the square root of the elevation's
     * sine (most of the change near the horizon, as in a real sky), and below the horizon a turn to the ground
     * colour within about 5° (the ground seen in a reflection).
     */
    static Vector3fc skyGradient(Vector3fc dir) {
        float up = dir.y();
        if (up >= 0) {
            return new Vector3f(HORIZON).lerp(ZENITH, (float) Math.sqrt(up));
        }
        float t = Math.min(1, -up / 0.09f); // sin 5° ≈ 0.09
        return new Vector3f(HORIZON).lerp(GROUND, t * t * (3 - 2 * t));
    }

    /** material.glsl's uniforms in one program, resolved once (the program must include material.glsl and use it). */
    public static Uniforms uniforms(ShaderProgram program) {
        return new Uniforms(program);
    }

    /**
     * Uses the program, binds the textures to units {@code firstUnit} .. {@code firstUnit + UNITS - 1} and sets the
     * settings' uniforms. Cheap: nothing is allocated, so settings may change every frame.
     */
    public void bind(Uniforms u, MaterialSettings settings, int firstUnit) {
        u.program.use();
        albedo.bind(firstUnit);
        detail.bind(firstUnit + 1);
        sky.bind(firstUnit + 2);
        u.albedo.set(firstUnit);
        u.detail.set(firstUnit + 1);
        u.sky.set(firstUnit + 2);
        u.detailScale.set((float) settings.detailScale());
        u.snowMode.set(switch (settings.snowMode()) { // material.glsl's MAT_SNOW_MAP and MAT_ALTITUDE_BANDS
            case SNOW_MAP -> 0;
            case ALTITUDE_BANDS -> 1;
        });
        u.normalMap.set(settings.normalMap() ? 1 : 0);
        u.glossMap.set(settings.glossMap() ? 1 : 0);
    }

    @Override
    public void close() {
        sky.close();
        detail.close();
        albedo.close();
    }

    /** The resolved uniform handles of material.glsl in one program. */
    public static final class Uniforms {
        private final ShaderProgram program;
        private final Uniform.Int albedo;
        private final Uniform.Int detail;
        private final Uniform.Int sky;
        private final Uniform.Float detailScale;
        private final Uniform.Int snowMode;
        private final Uniform.Int normalMap;
        private final Uniform.Int glossMap;

        private Uniforms(ShaderProgram program) {
            this.program = program;
            albedo = program.int1("uMatAlbedo");
            detail = program.int1("uMatDetail");
            sky = program.int1("uMatSky");
            detailScale = program.float1("uMatDetailScale");
            snowMode = program.int1("uMatSnowMode");
            normalMap = program.int1("uMatNormalMap");
            glossMap = program.int1("uMatGlossMap");
        }
    }
}

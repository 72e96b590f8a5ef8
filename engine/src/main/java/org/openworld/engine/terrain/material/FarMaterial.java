package org.openworld.engine.terrain.material;

import static org.lwjgl.opengl.GL30C.*;

import java.util.EnumMap;
import java.util.Map;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.OffscreenState;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Texture2D;
import org.openworld.engine.terrain.heights.HeightMap;

/**
 * The far terrain's material, baked: steps 1–3 of {@code shaders/terrain/material/material.glsl} (which material,
 * how they layer, their albedo, detail slope and gloss) evaluated once per texel of two textures laid over the map
 * tile, as a viewer far away sees them ({@code shaders/terrain/material/bake.frag}). Far patches read them with two
 * lookups where the near ones sample every layer at two scales (twelve lookups) and evaluate two 4-octave noises; their mips serve ever
 * farther ground.
 *
 * <p><b>Size.</b> One texel per height sample up to {@value #MAX_SIZE}² (2 m at the default 4 km tile, 1 m on a
 * 1 km one), then one per sample of the pyramid level with that many: an 8192² map bakes at 8 m. Colour in
 * SRGB8_ALPHA8 (albedo in sRGB, gloss linear), the detail slope and the ground's gradient in RGBA16F (the slope's x,
 * z encoded {@code s * 0.5 + 0.5}, the gradient as it is, so far patches need not read the gradient map as well),
 * both with mips: 64 MiB at 2048².
 *
 * <p><b>When.</b> At start and again when a setting it depends on changes ({@code materials.snow-mode},
 * {@code materials.detail-scale}, {@code materials.tiling}): one full-screen pass over the textures, then their
 * mips (with the extra programs, a shot's start-up on llvmpipe grows by about 0.2 s).
 *
 * <p><b>Limits.</b> A texel is a mean: detail finer than a texel (the fine tile, a blade of grass, a blend edge
 * sharper than a texel) is gone, and the mean slope lights like one normal, not like the many it stands for (a
 * rough surface's highlight is wider than that). A generated tile's macro variation is made periodic by fading each
 * edge into the opposite one, so within {@code 2 · MAT_MACRO_SCALE} of a tile edge the far ground's variation is not
 * the near ground's. The bake projects the rock from above whatever {@code materials.cliffs} says: a texel is a mean,
 * the same in any projection, and a far cliff gets a texel every {@code texelMetres / cos a} down its fall line.
 */
public final class FarMaterial {

    /** Texels along the side of the baked texture, at most. */
    static final int MAX_SIZE = 2048;
    /** The near material fades into the far one over this last fraction of the far distance. */
    public static final double BLEND_FRACTION = 0.3;

    private final GlContext gl;
    private final Texture2D colour;
    private final Texture2D slope;
    private final Map<MaterialSettings.Tiling, TerrainMaterials.Uniforms> bakes =
            new EnumMap<>(MaterialSettings.Tiling.class);
    private final Mesh triangle;
    private final double texelMetres;
    private MaterialSettings.SnowMode bakedSnow;
    private double bakedScale = Double.NaN;
    private MaterialSettings.Tiling bakedTiling;

    /**
     * Makes the textures and the bake programs, one per {@link MaterialSettings.Tiling tiling}, handed to the
     * system's owner ({@code terrain.far-material.colour}, {@code terrain.far-material.slope}, {@code terrain.bake},
     * {@code terrain.bake.quilted}, {@code terrain.bake.stochastic}); nothing is baked until {@link #refresh}.
     *
     * @param lowest        the height, metres, the materials read as normalised 0 (the map's lowest, or 0 m at true
     *                      scale)
     * @param highest       the height read as normalised 1
     * @param unitHeights   texture unit the caller binds the height pyramid to before a refresh; then the gradients
     *                      and the snow map on the next two units
     */
    public FarMaterial(EngineContext context, HeightMap base, float lowest, float highest, int unitHeights) {
        this.gl = context.gl();
        int size = Math.min(base.size(), MAX_SIZE);
        texelMetres = base.extent() / size;
        Sampling wrap = base.periodic() ? Sampling.TRILINEAR_REPEAT : Sampling.TRILINEAR_CLAMP;
        colour = context.own("far-material.colour", Texture2D.withMips(gl, size, size, Format.SRGB8_ALPHA8, wrap));
        slope = context.own("far-material.slope", Texture2D.withMips(gl, size, size, Format.RGBA16F, wrap));
        triangle = context.own(Mesh.fullScreenTriangle(gl));
        for (MaterialSettings.Tiling tiling : MaterialSettings.Tiling.values()) {
            ShaderProgram program = context.own("bake" + tiling.roleSuffix(),
                    context.shaders().program(tiling.defines(), "terrain/material/bake.vert",
                            "terrain/material/bake.frag"));
            bakes.put(tiling, bakeUniforms(program, base, lowest, highest, size, unitHeights));
        }
    }

    private static TerrainMaterials.Uniforms bakeUniforms(ShaderProgram program, HeightMap base, float lowest,
                                                          float highest, int size, int unitHeights) {
        program.use();
        program.sampler("heights", unitHeights);
        program.sampler("gradients", unitHeights + 1);
        program.sampler("snowMap", unitHeights + 2);
        program.int1("mapSize").set(base.size());
        program.float1("spacing").set((float) base.spacing());
        program.int1("periodic").set(base.periodic() ? 1 : 0);
        program.float1("extent").set((float) base.extent());
        program.vec2("heightRange").set(lowest, 1f / Math.max(1e-3f, highest - lowest));
        program.int1("bakeLevel").set(Integer.numberOfTrailingZeros(base.size() / size));
        program.vec2("bakeSize").set(size, size);
        return TerrainMaterials.layerUniforms(program);
    }

    /** Metres of ground along the side of one baked texel. */
    public double texelMetres() {
        return texelMetres;
    }

    /** Binds the baked colour and gloss to {@code unit}, the detail slope and gradient to {@code unit + 1}. */
    public void bind(int unit) {
        colour.bind(unit);
        slope.bind(unit + 1);
    }

    /**
     * Bakes if nothing was baked yet or the snow mode, the detail tile's size or the tiling changed since the last
     * bake: the caller has bound the maps (see the constructor); the materials take units {@code materialUnit}
     * onwards.
     * Leaves the framebuffer, viewport, depth test, blending and face culling as they were; the program in use and
     * the texture bindings of the materials' units change.
     */
    public void refresh(TerrainMaterials materials, MaterialSettings settings, int materialUnit) {
        if (settings.snowMode() == bakedSnow && settings.detailScale() == bakedScale
                && settings.tiling() == bakedTiling) {
            return;
        }
        materials.bind(bakes.get(settings.tiling()), settings, materialUnit);
        try (OffscreenState state = OffscreenState.enter();
             Framebuffer target = Framebuffer.onTextures(gl, colour, slope)) {
            target.bind();
            // linear albedo in, sRGB stored (the precision goes to the dark tones); the half-float slopes as they are
            glEnable(GL_FRAMEBUFFER_SRGB);
            triangle.draw(new DrawStats());
            glDisable(GL_FRAMEBUFFER_SRGB);
        }
        colour.generateMipmaps();
        slope.generateMipmaps();
        bakedSnow = settings.snowMode();
        bakedScale = settings.detailScale();
        bakedTiling = settings.tiling();
    }

}

package org.openworld.engine.terrain;

import java.util.EnumMap;
import java.util.Map;
import java.util.function.Function;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.Owned;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Uniform;
import org.openworld.engine.terrain.TerrainVariant.Kind;
import org.openworld.engine.terrain.TerrainVariant.Light;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.StageTimes;
import org.openworld.engine.terrain.lod.PatchList;
import org.openworld.engine.terrain.material.FarMaterial;
import org.openworld.engine.terrain.material.MaterialSettings;
import org.openworld.engine.terrain.material.TerrainMaterials;
import org.openworld.engine.terrain.material.GrassAlbedo;
import org.openworld.engine.terrain.material.TerrainTextures;
import org.openworld.engine.terrain.mesh.PatchLayout;
import org.openworld.engine.terrain.mesh.PatchOrder;
import org.openworld.engine.terrain.mesh.PatchRenderer;

/**
 * The terrain's colour in the passes that see it (main, reflection): materials that cost less with distance, and a
 * program per view so no pixel pays for a view it does not show.
 *
 * <p><b>Near and far.</b> Patches whose box lies nearer than D = {@code materials.far-texels} baked texels (300 m by
 * default) run the near program:
 * every layer of {@code material.glsl} (three materials at two scales, two 4-octave noises). The rest run the far
 * program: two lookups in the {@link FarMaterial} baked at start (colour and gloss, detail slope). Between
 * (1 − {@link FarMaterial#BLEND_FRACTION})·D and D the near program fades its material into the baked one, which it
 * also reads, and from D on shows only that; so where a near patch meets a far one both show the same colour, and
 * nothing pops as a patch changes program. Both programs light the far ground with the sky read per vertex.
 *
 * <p><b>The unbounded world's far ground.</b> A bake per level of the streamed clipmap would hold one texel per
 * height sample: 5 to 10 pixels a texel at 1280×720 where the tile's 2 m bake shows 1 to 5, its texture grain
 * averaged away. So there the far program makes the material as the near one does, at the coarse scale alone
 * ({@code MAT_COARSE_ONLY}: six lookups instead of twelve), its sky read per vertex as on the tile, and the near
 * program fades its fine scale out over the same band; D is counted in level 0's samples. On llvmpipe at 1280×720
 * along the crossing this took the streamed frame from 274 to 220 ms (docs/terrain.md, section 5).
 *
 * <p><b>Shadows.</b> The near and far programs come twice: reading the sun's shadow maps, and compiled without the
 * lookup ({@code SUN_UNSHADOWED}, {@code shaders/common/shadow.glsl}) for the passes where no map is bound (no shadow
 * system, or it is switched off). A map that shadows nothing would give the same picture, but a software rasteriser
 * runs a loop's body at least once, masked, whatever its count: the lookup cost a fifth of the terrain's pixel time
 * with no shadows to show.
 *
 * <p><b>Views.</b> The debug colourings are programs of their own: {@code levels} is the far program tinted by the
 * patch's level (figure 6: only the light's lightness matters there), {@code tangent-space} reads no material
 * (figure 4).
 *
 * <p><b>Cost.</b> On llvmpipe, at 1280×720 over the peer's view, the near program costs about four times the far one
 * per pixel (docs/terrain.md has the measured split).
 *
 * <p><b>Variants.</b> Each program is a {@link TerrainVariant} (kind × tiling × cliffs × light × layout), which names
 * its defines and its role; they compile on their first use, so only the ones a frame draws are built.
 */
final class TerrainShading {

    /** A near program (one tiling, one kind of sunlight) with its material uniforms and its far band. */
    private record Near(TerrainMaterials.Uniforms uniforms, Uniform.Vec2 farBand) {
    }

    /**
     * The near and the far programs for one kind of sunlight, per tiling: on the tile one far program for all, which
     * reads the bake; on the unbounded world one per tiling, which samples the materials.
     */
    private record Lit(Map<MaterialSettings.Tiling, Near> near,
                       Map<MaterialSettings.Tiling, TerrainMaterials.Uniforms> far) {
    }

    private final Lit shadowed;
    private final Lit unshadowed;
    private final ShaderProgram tangentSpace;
    private final TerrainMaterials.Uniforms levelsUniforms;
    private final GlContext gl;
    private final Owned owned;
    private final int seed;
    private final StageTimes times;
    /** The synthesised tiles, kept to quilt from when {@code materials.tiling} turns to quilted. */
    private final TerrainTextures tiles;
    private final GrassAlbedo grass;
    private TerrainMaterials materials;
    private boolean quilted;
    private final PatchLayout layout;
    /** Where the programs read the heights, as their variants name it. */
    private final TerrainVariant.Layout heights;
    /** How the ground beyond the far distance is coloured: the tile's bake, or the materials' coarse scale. */
    private final Far far;
    private final int unitMaterials;
    private final int unitGradients;
    private final int unitFar;
    /** The far field's material uniforms, once {@link #farField} made its program. */
    private TerrainMaterials.Uniforms farFieldUniforms;
    private double originX;   // the render origin of the pass, metres (origin.RenderOrigin)
    private double originZ;

    /**
     * The shading of a tile, its far ground baked over {@code base} ({@link #bake} bakes it).
     *
     * @param unitHeights the unit of the height pyramid; the gradients and the snow map take the next two, the
     *                    materials the {@link TerrainMaterials#UNITS} after those, then the far material two
     */
    static TerrainShading baked(EngineContext context, PatchLayout layout, HeightMap base, int seed, int unitHeights,
                                StageTimes times) {
        return new TerrainShading(context, layout, TerrainVariant.Layout.TILE, seed, unitHeights, times,
                shading -> shading.new Baked(new FarMaterial(context, base, layout.lowest(), layout.highest(),
                        unitHeights)));
    }

    /**
     * The shading of streamed levels: no bake, the programs read the slopes and the snow of the clipmap on the
     * gradients' and the snow map's units, and the far program samples the materials at the coarse scale alone.
     */
    static TerrainShading coarse(EngineContext context, PatchLayout layout, int seed, int unitHeights,
                                 StageTimes times) {
        return new TerrainShading(context, layout, TerrainVariant.Layout.CLIPMAP, seed, unitHeights, times,
                shading -> shading.new Coarse());
    }

    /**
     * Makes the programs, the materials (quilted if the settings of the start ask for it, timed as the
     * {@code quilting} stage) and the far look, handed to the system's owner.
     */
    private TerrainShading(EngineContext context, PatchLayout layout, TerrainVariant.Layout heights, int seed,
                           int unitHeights, StageTimes times, Function<TerrainShading, Far> far) {
        unitGradients = unitHeights + 1;
        unitMaterials = unitHeights + 3;
        unitFar = unitMaterials + TerrainMaterials.UNITS; // and the next: colour, slope
        gl = context.gl();
        owned = context.owned();
        this.seed = seed;
        this.times = times;
        tiles = TerrainTextures.generate(seed);
        grass = GrassAlbedo.of(tiles);
        materials = context.own("materials", upload(context.settings().get(MaterialSettings.class).tiling()));
        this.layout = layout;
        this.heights = heights;
        this.far = far.apply(this);
        MaterialSettings.Cliffs cliffs = context.settings().get(MaterialSettings.class).cliffs();
        shadowed = lit(context, Light.SHADOWED, cliffs, unitHeights);
        unshadowed = lit(context, Light.UNSHADOWED, cliffs, unitHeights);
        ShaderProgram levels = variant(context, TerrainVariant.of(Kind.LEVELS, heights), unitHeights);
        levelsUniforms = this.far.reads(levels, unitHeights); // the far look, tinted
        tangentSpace = variant(context, TerrainVariant.of(Kind.TANGENT_SPACE, heights), unitHeights);
        tangentSpace.sampler(layout.slopeSampler(), unitGradients);
    }

    /** What the grass's blades thin into: the ground's grass, with its sheen only while the gloss maps are on. */
    GrassAlbedo grass(MaterialSettings settings) {
        return settings.glossMap() ? grass : grass.withoutSheen();
    }

    /**
     * Bakes the far material with these settings, outside any pass (its textures made, the maps bound to their units
     * since); nothing for the streamed world.
     */
    void bake(MaterialSettings settings) {
        far.refresh(settings);
    }

    /** The materials' textures for this tiling: the tiles, or the Wang tiles quilted from them now. */
    private TerrainMaterials upload(MaterialSettings.Tiling tiling) {
        quilted = tiling == MaterialSettings.Tiling.QUILTED;
        return new TerrainMaterials(gl, quilted ? times.time("quilting", () -> tiles.quilted(seed)) : tiles);
    }

    /**
     * The near programs, one per tiling, and the far ones (on the tile one that reads the bake, on the unbounded
     * world one per tiling) for this light; the near ones project the rock as {@code cliffs} says.
     */
    private Lit lit(EngineContext context, Light light, MaterialSettings.Cliffs cliffs, int unitHeights) {
        Map<MaterialSettings.Tiling, Near> near = new EnumMap<>(MaterialSettings.Tiling.class);
        Map<MaterialSettings.Tiling, TerrainMaterials.Uniforms> far = new EnumMap<>(MaterialSettings.Tiling.class);
        for (MaterialSettings.Tiling tiling : MaterialSettings.Tiling.values()) {
            ShaderProgram p = variant(context, new TerrainVariant(Kind.NEAR, tiling, cliffs, light, heights),
                    unitHeights);
            nearSamplers(p, unitHeights);
            near.put(tiling, new Near(TerrainMaterials.uniforms(p), p.vec2("farBand")));
        }
        this.far.programs(context, light, unitHeights, far);
        return new Lit(near, far);
    }

    /**
     * The far field's program ({@link FarField}): its ring ({@code terrain/farfield.vert}) coloured by the far
     * program, without the sun's shadows (it lies beyond every cascade); on the unbounded world the materials at the
     * coarse scale of the repeat tiling (far off, every tiling's mips average to the same colour), on the tile the
     * baked far material. Its maps' samplers are set; {@link #bindFarField} binds the materials.
     */
    ShaderProgram farField(EngineContext context, int unitHeights) {
        ShaderProgram p = TerrainVariant.of(Kind.FAR_FIELD, heights).program(context);
        p.use();
        p.sampler("heights", unitHeights);
        p.sampler("snowMap", unitHeights + 2);
        farFieldUniforms = far.reads(p, unitHeights);
        layout.extentUniforms(p);
        return p;
    }

    /** The program of the passes that need depth alone (the sun's), its vertex stage's uniforms set. */
    ShaderProgram depth(EngineContext context, int unitHeights) {
        ShaderProgram p = TerrainVariant.of(Kind.DEPTH, heights).program(context);
        layout.apply(p, unitHeights);
        return p;
    }

    /** The render origin the next draws measure positions from, metres. */
    void origin(double x, double z) {
        originX = x;
        originZ = z;
    }

    /** Uses the far field's program with the materials of the moment ({@link #draw} refreshed them). */
    void bindFarField(MaterialSettings settings) {
        materials.bind(farFieldUniforms, settings, unitMaterials, originX, originZ);
    }

    /** A near program's maps: the slopes, or the gradients, the snow map and the far material it fades into. */
    private void nearSamplers(ShaderProgram p, int unitHeights) {
        p.vec2("heightRange").set(layout.lowest(), 1f / Math.max(1e-3f, layout.highest() - layout.lowest()));
        p.sampler("snowMap", unitHeights + 2);
        p.sampler(layout.slopeSampler(), unitGradients); // the far programs read the gradient from the far look
        far.fadesInto(p);
    }

    private static void farSamplers(ShaderProgram p, int unitFar) {
        p.sampler("farColour", unitFar);
        p.sampler("farSlope", unitFar + 1);
    }

    /** A terrain program with the patch uniforms and the maps' extent set. */
    private ShaderProgram variant(EngineContext context, TerrainVariant variant, int unitHeights) {
        ShaderProgram p = variant.program(context);
        layout.apply(p, unitHeights);
        layout.extentUniforms(p);
        return p;
    }

    /**
     * Draws the ordered patches in the colouring asked for, near ones first; the maps are bound to their units.
     * Quilts the textures (or goes back to the tiles) first if {@code materials.tiling} turned to or from quilted,
     * and bakes the far material again if a setting it depends on changed. {@code sunShadowed}: the pass has the
     * sun's shadow maps bound (RenderContext#shares), else the programs without the lookup draw. Returns how
     * many patches the near program drew (all of them in the debug colourings).
     */
    int draw(PatchList patches, PatchOrder order, float[] copyOffsets, MaterialSettings settings,
             TerrainDebugSettings.Colouring colouring, boolean sunShadowed, PatchRenderer renderer,
             DrawStats stats) {
        if ((settings.tiling() == MaterialSettings.Tiling.QUILTED) != quilted) {
            materials = owned.replace("materials", materials, upload(settings.tiling()));
        }
        int all = order.size();
        far.refresh(settings);
        far.bind();
        return switch (colouring) {
            case SHADED -> {
                Lit lit = sunShadowed ? shadowed : unshadowed;
                Near near = lit.near().get(settings.tiling());
                materials.bind(near.uniforms(), settings, unitMaterials, originX, originZ);
                double farDistance = settings.farTexels() * far.texelMetres();
                int nearCount = order.nearerThan(farDistance);
                near.farBand().set((float) (farDistance * (1 - FarMaterial.BLEND_FRACTION)), (float) farDistance);
                renderer.draw(patches, order.order(), 0, nearCount, copyOffsets, stats);
                materials.bind(lit.far().get(settings.tiling()), settings, unitMaterials, originX, originZ);
                renderer.draw(patches, order.order(), nearCount, all, copyOffsets, stats);
                yield nearCount;
            }
            case LEVELS -> {
                materials.bind(levelsUniforms, settings, unitMaterials, originX, originZ);
                renderer.draw(patches, order.order(), 0, all, copyOffsets, stats);
                yield all;
            }
            case TANGENT_SPACE -> {
                tangentSpace.use();
                renderer.draw(patches, order.order(), 0, all, copyOffsets, stats);
                yield all;
            }
        };
    }

    /** How the ground beyond the far distance D is coloured, and what the near programs fade into before D. */
    private interface Far {
        /** Sets the samplers a program reading the far look needs; its material uniforms. */
        TerrainMaterials.Uniforms reads(ShaderProgram p, int unitHeights);
        /** Sets what a near program reads of the far look it fades into. */
        void fadesInto(ShaderProgram p);
        /** Makes the far programs of one kind of sunlight, per tiling, into {@code far}. */
        void programs(EngineContext context, Light light, int unitHeights,
                      Map<MaterialSettings.Tiling, TerrainMaterials.Uniforms> far);
        /** Brings the far look up to these settings (bakes again if they changed it). */
        void refresh(MaterialSettings settings);
        /** Binds what the far programs read. */
        void bind();
        /** Metres of one far texel, the unit of {@code materials.far-texels}. */
        double texelMetres();
    }

    /** The tile: the materials baked once over the tile ({@link FarMaterial}), one far program for every tiling. */
    private final class Baked implements Far {

        private final FarMaterial material;

        Baked(FarMaterial material) {
            this.material = material;
        }

        @Override
        public TerrainMaterials.Uniforms reads(ShaderProgram p, int unitHeights) {
            farSamplers(p, unitFar);
            return TerrainMaterials.lightUniforms(p);
        }

        @Override
        public void fadesInto(ShaderProgram p) {
            farSamplers(p, unitFar);
        }

        @Override
        public void programs(EngineContext context, Light light, int unitHeights,
                             Map<MaterialSettings.Tiling, TerrainMaterials.Uniforms> far) {
            // one program: the baked material, lit, its sky per vertex
            ShaderProgram f = variant(context, TerrainVariant.far(MaterialSettings.Tiling.REPEAT, light, heights),
                    unitHeights);
            farSamplers(f, unitFar);
            f.sampler("snowMap", unitHeights + 2); // the sky's visibility, per vertex
            TerrainMaterials.Uniforms baked = TerrainMaterials.lightUniforms(f);
            for (MaterialSettings.Tiling tiling : MaterialSettings.Tiling.values()) {
                far.put(tiling, baked);
            }
        }

        @Override
        public void refresh(MaterialSettings settings) {
            material.refresh(materials, settings, unitMaterials);
        }

        @Override
        public void bind() {
            material.bind(unitFar);
        }

        @Override
        public double texelMetres() {
            return material.texelMetres();
        }
    }

    /** Streamed levels: nothing baked, the far programs make the material at its coarse scale, one per tiling. */
    private final class Coarse implements Far {

        @Override
        public TerrainMaterials.Uniforms reads(ShaderProgram p, int unitHeights) {
            nearSamplers(p, unitHeights);
            return TerrainMaterials.uniforms(p);
        }

        @Override
        public void fadesInto(ShaderProgram p) {
            // the near program fades its fine scale out: it reads nothing more
        }

        @Override
        public void programs(EngineContext context, Light light, int unitHeights,
                             Map<MaterialSettings.Tiling, TerrainMaterials.Uniforms> far) {
            for (MaterialSettings.Tiling tiling : MaterialSettings.Tiling.values()) {
                // the materials at the coarse scale, its sky per vertex
                ShaderProgram f = variant(context, TerrainVariant.far(tiling, light, heights), unitHeights);
                nearSamplers(f, unitHeights);
                far.put(tiling, TerrainMaterials.uniforms(f));
            }
        }

        @Override
        public void refresh(MaterialSettings settings) {
        }

        @Override
        public void bind() {
        }

        @Override
        public double texelMetres() {
            return layout.spacing();
        }
    }
}

package org.openworld.engine.terrain;

import java.util.List;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Uniform;

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
 * nothing pops as a patch changes program.
 *
 * <p><b>Views.</b> The debug colourings are programs of their own: {@code levels} is the far program tinted by the
 * patch's level (figure 6: only the light's lightness matters there), {@code tangent-space} reads no material
 * (figure 4).
 *
 * <p><b>Cost.</b> On llvmpipe, at 1280×720 over the peer's view, the near program costs about four times the far one
 * per pixel (docs/terrain.md has the measured split). Six programs are compiled at start instead of two.
 */
final class TerrainShading {

    private final ShaderProgram near;
    private final ShaderProgram far;
    private final ShaderProgram levels;
    private final ShaderProgram tangentSpace;
    private final TerrainMaterials.Uniforms nearUniforms;
    private final TerrainMaterials.Uniforms farUniforms;
    private final TerrainMaterials.Uniforms levelsUniforms;
    private final Uniform.Vec2 farBand;
    private final TerrainMaterials materials;
    private final FarMaterial farMaterial;
    private final int unitMaterials;
    private final int unitFar;

    /**
     * Makes the programs, the materials and the far material, handed to the system's owner, and bakes the far
     * material with the settings of the start.
     *
     * @param unitHeights   the unit of the height pyramid; the gradients and the snow map take the next two, the
     *                      materials the {@link TerrainMaterials#UNITS} after those, then the far material two
     */
    TerrainShading(EngineContext context, TerrainMaps maps, HeightMap base, int cells, int seed, int unitHeights) {
        int unitGradients = unitHeights + 1;
        int unitSnow = unitHeights + 2;
        unitMaterials = unitHeights + 3;
        unitFar = unitMaterials + TerrainMaterials.UNITS; // and the next: colour, slope
        materials = context.own("materials", new TerrainMaterials(context.gl(), seed));
        farMaterial = new FarMaterial(context, base, unitHeights);
        near = variant(context, "program", List.of(), base, cells, unitHeights);
        far = variant(context, "program.far", List.of("TERRAIN_FAR"), base, cells, unitHeights);
        levels = variant(context, "program.levels", List.of("TERRAIN_FAR", "TERRAIN_LEVELS"), base, cells, unitHeights);
        tangentSpace = variant(context, "program.tangent-space", List.of("TERRAIN_TANGENT_SPACE"), base, cells,
                unitHeights);
        for (ShaderProgram p : List.of(near, far, levels, tangentSpace)) {
            p.use();
            p.float1("extent").set((float) base.extent());
        }
        near.sampler("gradients", unitGradients); // the far programs read the gradient from the far material
        tangentSpace.sampler("gradients", unitGradients);
        for (ShaderProgram p : List.of(near, far, levels)) {
            p.sampler("farColour", unitFar);
            p.sampler("farSlope", unitFar + 1);
        }
        near.sampler("snowMap", unitSnow);
        near.vec2("heightRange").set(base.min(), 1f / Math.max(1e-3f, base.max() - base.min()));
        farBand = near.vec2("farBand");
        nearUniforms = TerrainMaterials.uniforms(near);
        farUniforms = TerrainMaterials.lightUniforms(far);
        levelsUniforms = TerrainMaterials.lightUniforms(levels);
        maps.heights.bind(unitHeights);
        maps.gradients.bind(unitGradients);
        maps.snow.bind(unitSnow);
        farMaterial.refresh(materials, context.settings().get(MaterialSettings.class), unitMaterials);
    }

    private static ShaderProgram variant(EngineContext context, String role, List<String> defines, HeightMap base,
                                         int cells, int unitHeights) {
        ShaderProgram p = context.own(role,
                context.shaders().program(defines, "terrain/terrain.vert", "terrain/terrain.frag"));
        TerrainSystem.setPatchUniforms(p, base, cells, unitHeights);
        return p;
    }

    /**
     * Draws the ordered patches in the colouring asked for, near ones first; the maps are bound to their units.
     * Bakes the far material again first if a setting it depends on changed.
     */
    void draw(PatchList patches, PatchOrder order, float[] copyOffsets, MaterialSettings settings,
              TerrainDebugSettings.Colouring colouring, PatchRenderer renderer, DrawStats stats) {
        farMaterial.refresh(materials, settings, unitMaterials);
        farMaterial.bind(unitFar);
        int all = order.size();
        switch (colouring) {
            case SHADED -> {
                double farDistance = settings.farTexels() * farMaterial.texelMetres();
                int nearCount = order.nearerThan(farDistance);
                materials.bind(nearUniforms, settings, unitMaterials);
                farBand.set((float) (farDistance * (1 - FarMaterial.BLEND_FRACTION)), (float) farDistance);
                renderer.draw(patches, order.order(), 0, nearCount, copyOffsets, stats);
                materials.bind(farUniforms, settings, unitMaterials);
                renderer.draw(patches, order.order(), nearCount, all, copyOffsets, stats);
            }
            case LEVELS -> {
                materials.bind(levelsUniforms, settings, unitMaterials);
                renderer.draw(patches, order.order(), 0, all, copyOffsets, stats);
            }
            case TANGENT_SPACE -> {
                tangentSpace.use();
                renderer.draw(patches, order.order(), 0, all, copyOffsets, stats);
            }
        }
    }
}

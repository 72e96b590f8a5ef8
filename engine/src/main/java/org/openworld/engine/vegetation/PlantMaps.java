package org.openworld.engine.vegetation;

import org.openworld.engine.core.EngineContext;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.TextureArray;
import org.openworld.engine.gl.TextureUnits;

/**
 * The plants' synthesised textures on the GPU: the {@link BarkTextures} as two trilinear, mipmapped, repeating
 * texture arrays (albedo in sRGB, so sampling returns linear values; detail), layer = the bark. The mipmaps keep far
 * trunks from shimmering: a minified trunk samples the bark's mean, as the impostors' bake does at its 64-texel
 * frames. Bound for the meshes ({@link TreeDraw}) and the bake ({@link ImpostorAtlas}) alike, so the two agree.
 */
final class PlantMaps {

    private static final TextureUnits UNITS = new TextureUnits();
    private static final TextureUnits.Sampler BARK_ALBEDO = UNITS.add("uBarkAlbedo");
    private static final TextureUnits.Sampler BARK_DETAIL = UNITS.add("uBarkDetail");

    private final TextureArray albedo;
    private final TextureArray detail;

    /** Uploads textures synthesised beforehand; the context owns (and closes) them. */
    PlantMaps(EngineContext context, BarkTextures bark) {
        int n = BarkTextures.SIZE;
        albedo = context.own("barkAlbedo", TextureArray.repeatingMipmapped(context.gl(), n, n, Format.SRGB8_ALPHA8,
                bark.albedo()));
        detail = context.own("barkDetail", TextureArray.repeatingMipmapped(context.gl(), n, n, Format.RGBA8,
                bark.detail()));
    }

    /** Points a program's bark samplers at their units (once, after linking). */
    static void samplers(ShaderProgram program) {
        program.sampler(BARK_ALBEDO);
        program.sampler(BARK_DETAIL);
    }

    /** Binds the textures to their units (before each pass's draws: other programs use the same units). */
    void bind() {
        albedo.bind(BARK_ALBEDO.unit());
        detail.bind(BARK_DETAIL.unit());
    }
}

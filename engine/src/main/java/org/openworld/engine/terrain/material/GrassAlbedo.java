package org.openworld.engine.terrain.material;

import org.openworld.engine.colour.Lab;
import org.openworld.engine.terrain.material.TerrainTextures.Material;

/**
 * The ground's grass as a meadow seen from afar: the mean linear albedo of the grass texture's texels, times the mean
 * of the macro variation that {@code terrain/material/material.glsl} lays over it ({@code terrainMaterial}'s
 * {@code mix(vec3(0.75, 0.85, 0.8), vec3(1.3, 1.15, 0.8), tint) · (0.8 + 0.4 · macro)} at its mean tint and macro,
 * 0.5). Published by the terrain as a world resource when it makes its textures, so what stands on the ground (the
 * grass's blades) can take on the ground's colour where it thins away.
 *
 * <p>And its sheen: the mean over the texels of the squared gloss, the share of the sky's light the terrain reflects
 * towards a grazing look ({@code lightTerrain}'s sky reflection, {@code fresnel · gloss²}); a meadow seen from near
 * its own height shines with it.
 *
 * @param r     linear red, green and blue, 0 to 1
 * @param sheen the mean squared gloss, 0 to 1
 */
public record GrassAlbedo(float r, float g, float b, float sheen) {

    /** The macro variation's mean factor per channel (material.glsl, at tint = macro = 0.5). */
    static final float[] MACRO_MEAN = {1.025f, 1.0f, 0.8f};

    /** The mean over the grass layer's texels of {@code textures}, linear, under the macro variation's mean. */
    public static GrassAlbedo of(TerrainTextures textures) {
        byte[] texels = textures.albedo(Material.GRASS);
        byte[] detail = textures.detail(Material.GRASS);
        double[] sum = new double[4];
        for (int k = 0; k < texels.length; k += 4) {
            for (int c = 0; c < 3; c++) {
                sum[c] += Lab.linear(texels[k + c] & 0xff);
            }
            double gloss = (detail[k + 3] & 0xff) / 255.0;
            sum[3] += gloss * gloss;
        }
        double n = texels.length / 4.0;
        return new GrassAlbedo((float) (sum[0] / n * MACRO_MEAN[0]), (float) (sum[1] / n * MACRO_MEAN[1]),
                (float) (sum[2] / n * MACRO_MEAN[2]), (float) (sum[3] / n));
    }

    /** The same colour without a sheen: the terrain's look while its gloss maps are off. */
    public GrassAlbedo withoutSheen() {
        return new GrassAlbedo(r, g, b, 0);
    }
}

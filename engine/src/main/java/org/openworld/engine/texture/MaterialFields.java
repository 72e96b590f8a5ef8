package org.openworld.engine.texture;

/**
 * One material's surface before encoding, n² texels each, texel (x, y) at {@code y n + x}: what a
 * recipe (the terrain's {@code MaterialRecipes}, the plants' {@code BarkTextures}) makes and {@link MaterialEncoding} packs into the GPU's bytes.
 *
 * @param red    linear red reflectance, 0..1
 * @param green  linear green reflectance, 0..1
 * @param blue   linear blue reflectance, 0..1
 * @param height relief height, texels (the normal's source: one texel up over one texel across is 45°)
 * @param gloss  glossiness, 0..1 (specular power and reflection strength)
 */
public record MaterialFields(float[] red, float[] green, float[] blue, float[] height, float[] gloss) {
}

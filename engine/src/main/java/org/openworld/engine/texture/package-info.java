/**
 * Texture synthesis from spectra, shared by the systems that make their surfaces at start (the terrain's materials,
 * the plants' bark): no downloaded art.
 *
 * <p><b>Technique.</b> {@link org.openworld.engine.texture.PeriodicNoise}: Gaussian fields with a radial 1/f^β
 * amplitude spectrum over whole cycles per tile, {@code A(f²) = exp(−(low²/f²)² − (f²/high²)²) · f^(−β/2)}, brought
 * back by one inverse FFT, so periodic over the tile by construction. A recipe (the terrain's
 * {@code MaterialRecipes}, the plants' {@code BarkTextures}) turns such fields into a
 * {@link org.openworld.engine.texture.MaterialFields} of linear colour, relief and gloss;
 * {@link org.openworld.engine.texture.MaterialEncoding} packs that into an sRGB albedo and a detail texture (the
 * tangent-space normal from the relief's wrapped central differences, the relief, the gloss).
 *
 * <p><b>Data path.</b> Recipe (any thread) → two RGBA8 byte arrays per tile → the owner's mipmapped texture array.
 *
 * <p><b>Cost.</b> One complex n² inverse FFT per pair of fields, O(n² log n) (about 16 ms at 512² on the 2-core
 * reference machine, JIT warm), and one pass over the texels per texture.
 *
 * <p><b>Limits.</b> Gaussian and isotropic: ridges, edges and a direction come from the recipes (thresholds, cells,
 * stamping, reading a field squeezed across).
 */
package org.openworld.engine.texture;

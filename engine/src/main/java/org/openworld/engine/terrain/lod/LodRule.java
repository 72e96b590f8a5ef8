package org.openworld.engine.terrain.lod;

/**
 * When a terrain patch is fine enough ({@code lod.rule}); a pass turns it into a {@link DetailLimit}.
 */
public enum LodRule {
    /**
     * The projected geometric error: a node is drawn at its level once the largest height difference between its
     * level and the finest one, seen from the pass's camera, covers at most {@code lod.pixel-error} pixels (the sun's
     * pass takes the viewer's camera). Triangles go where the relief shows.
     */
    SCREEN_ERROR,
    /**
     * The paper's distance rule, equation 2: level {@link #level L_B(D)} at distance D, whatever the relief
     * ({@code lod.base-resolution} = B); reproduces figure 6.
     */
    PAPER;

    /**
     * The paper's equation 2, L_B(D) = ⌊log2(D / B)⌋, clamped at 0 (nearer than 2B a patch is drawn at full
     * resolution; no level is finer than the height samples). Exact: ⌊log2⌋ is read from the double's exponent.
     *
     * @param distance       D, metres
     * @param baseResolution B, metres, positive
     */
    public static int level(double distance, double baseResolution) {
        double ratio = distance / baseResolution;
        return ratio < 2 ? 0 : Math.getExponent(ratio);
    }
}

package org.openworld.engine.terrain.lod;

import org.joml.Matrix4fc;

/**
 * How fine the terrain must be in one pass: whether a patch drawn at a level is fine enough, or must be split into
 * finer ones. Made per pass from the {@link LodRule} ({@link LodSettings#limit}). GL-free.
 */
public sealed interface DetailLimit {

    /**
     * @param level    the patch's level L: its vertices 2^L samples apart
     * @param error    its geometric error, metres: the largest |height at level L − finest height| over its area
     *                 ({@link TerrainQuadtree#error})
     * @param distance from the eye to the nearest point of its box, metres
     */
    boolean fineEnough(int level, double error, double distance);

    /**
     * The distance from which a patch of this level and error is fine enough, metres: {@link #fineEnough} holds for
     * every distance at least this (0 when it always holds, positive infinity when it never does). Geomorphing
     * ({@link QuadtreeLod}) reads a node's merge distance from it: where its parent becomes fine enough.
     */
    double fineFrom(int level, double error);

    /** The paper's rule: level L is fine enough from distance D on when L ≤ L_B(D) ({@link LodRule#level}). */
    static DetailLimit paper(double baseResolution) {
        if (!(baseResolution > 0)) {
            throw new IllegalArgumentException("base resolution must be positive, got " + baseResolution);
        }
        return new Paper(baseResolution);
    }

    /**
     * A bound on the projected error for a camera's projection and the pixels of its target. Seen through a
     * perspective projection, a height error e at distance D covers e · f / D pixels, where f = (H/2) / tan(fov/2)
     * = (H/2) · P₁₁ is the focal length in pixels (the smaller of the two axes' for a non-square view); through an
     * orthographic one it covers e / t pixels, t = 2 / (P₁₁ · H) metres per pixel, whatever the distance (the sun's
     * pass does not use it: its casters take the viewer's limit, {@link LodSettings#limit}). The projection's bottom row tells the two apart: −1 in its third column for a
     * perspective, 0 for an orthographic one. An oblique near plane (the water's reflection) changes only the third
     * row, so f stays the viewer's.
     *
     * @param pixels the most pixels an error may cover, positive
     */
    static DetailLimit projected(Matrix4fc projection, int width, int height, double pixels) {
        if (!(pixels > 0)) {
            throw new IllegalArgumentException("pixel error must be positive, got " + pixels);
        }
        double focal = Math.min(Math.abs(projection.m00()) * width, Math.abs(projection.m11()) * height) / 2;
        return new Projected(focal, projection.m23() != 0, pixels);
    }

    /** The paper's distance rule with base resolution B, metres. */
    record Paper(double baseResolution) implements DetailLimit {
        @Override
        public boolean fineEnough(int level, double error, double distance) {
            return level <= LodRule.level(distance, baseResolution);
        }

        /** L ≤ ⌊log2(D / B)⌋ from D = B · 2^L on; level 0 always. */
        @Override
        public double fineFrom(int level, double error) {
            return level == 0 ? 0 : baseResolution * Math.pow(2, level);
        }
    }

    /**
     * error · focal / D ≤ pixels (perspective) or error · focal ≤ pixels (orthographic), written without a division
     * so that D = 0, a node around the eye, is never fine enough unless it has no error.
     *
     * @param focal       pixels per metre at unit distance (perspective) or pixels per metre (orthographic)
     * @param perspective whether the error shrinks with distance
     * @param pixels      the most pixels an error may cover
     */
    record Projected(double focal, boolean perspective, double pixels) implements DetailLimit {
        @Override
        public boolean fineEnough(int level, double error, double distance) {
            return error * focal <= pixels * (perspective ? distance : 1);
        }

        /** D = error · focal / pixels through a perspective; through an orthographic view always or never. */
        @Override
        public double fineFrom(int level, double error) {
            if (perspective) {
                return error * focal / pixels;
            }
            return error * focal <= pixels ? 0 : Double.POSITIVE_INFINITY;
        }
    }
}

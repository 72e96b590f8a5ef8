package org.openworld.engine.vegetation;

import java.util.Arrays;
import org.openworld.engine.core.HeightField;

/**
 * The forests past the plants' reach, as the far ground's material shows them
 * ({@link org.openworld.engine.environment.ForestCover}): for each texel of a window {@link #EXTENT} metres across
 * around the viewer, how much of the ground the canopy hides seen from above, and each kind's share of that canopy,
 * from the same {@link PlacementField} and rules the plants are placed by, so a forest is tinted where its trees
 * would stand, and nowhere the rules leave bare (water, snow, cliffs). No GL: made on the vegetation's worker.
 *
 * <p>With ρ plants per square metre ({@code vegetation.density · field}), a share {@code p_k} of them of kind k, each
 * hiding {@code a_k} square metres from above (its impostor's top view, {@link ImpostorAtlas#topArea}, times the
 * mean square of its height), the plants standing at random, the ground left in view is the chance that no crown
 * covers a point: {@code exp(−ρ Σ p_k a_k)} (a Poisson count of crowns over the point). The canopy's colour mixes
 * the kinds by {@code p_k a_k}.
 *
 * <p>Cost: {@link #SIZE}² texels of {@link #SUB}² points, each about 16 height lookups (the rules' slope and the
 * moisture's probes), on a worker thread, once per {@link #RECENTRE} metres of travel. Limits: 128 m texels, so
 * groves under that size blur into their surroundings; the cover is as seen from straight above, so a forest seen
 * at a grazing angle, whose trunks and crowns hide more ground than that, looks a little sparser as a tint than as
 * trees.
 */
final class FarForest {

    /** Texels per side of the window. */
    static final int SIZE = 256;
    /** Metres across the window: a power of two (ForestCover), 128 m texels, forests to 12 km round the viewer. */
    static final double EXTENT = 32768;
    /** Samples per side of a texel: the rules and the field averaged over 3 × 3 points 43 m apart. */
    static final int SUB = 3;
    /** Metres the viewer may move before the window is made again around it. */
    static final double RECENTRE = EXTENT / 8;
    /** Metres from the viewer the window always holds: half of it less the move before it is made again. */
    static final double REACH = EXTENT / 2 - RECENTRE;

    /**
     * A window's texels (RGBA8 bytes, rows of increasing z) and the point it was made around.
     *
     * @param x metres, world x of the viewer it was made around
     * @param z metres, world z
     */
    record Window(double x, double z, byte[] rgba) {
    }

    private FarForest() {
    }

    /**
     * The window around (x, z): texel (i, j) holds the point congruent to ((i + ½), (j + ½)) texels modulo the extent
     * that lies nearest (x, z).
     *
     * @param topArea each kind's crown from above, units of its height squared ({@link ImpostorAtlas#topArea})
     */
    static Window around(TreePlacer.World world, PlacementField field, double[] topArea, double x, double z) {
        VegetationSettings s = world.settings();
        HeightField heights = world.heights();
        double texel = EXTENT / SIZE;
        // a plant's height is uniform between the shortest and the tallest: the mean of its square
        double lo = s.minHeight();
        double hi = s.maxHeight();
        double meanSquare = (lo * lo + lo * hi + hi * hi) / 3;
        double[] area = new double[TreePlacement.KINDS];
        for (TreeKind kind : TreeKind.values()) {
            area[kind.ordinal()] = topArea[kind.ordinal()] * kind.scale * kind.scale * meanSquare;
        }
        byte[] rgba = new byte[SIZE * SIZE * 4];
        double[] kinds = new double[TreePlacement.KINDS];
        for (int j = 0; j < SIZE; j++) {
            double pz = nearest((j + 0.5) * texel, z);
            for (int i = 0; i < SIZE; i++) {
                double px = nearest((i + 0.5) * texel, x);
                // the crowns' area per square metre, averaged over SUB × SUB points of the texel: the rules pass or
                // fail point by point (a slope, a shore), so one point would stand for the whole texel
                Arrays.fill(kinds, 0);
                for (int b = 0; b < SUB; b++) {
                    for (int a = 0; a < SUB; a++) {
                        double sx = px + ((a + 0.5) / SUB - 0.5) * texel;
                        double sz = pz + ((b + 0.5) / SUB - 0.5) * texel;
                        double h = heights.heightAt(sx, sz);
                        if (!world.limits().allow(h, TreePlacement.gradient(heights, sx, sz))) {
                            continue;
                        }
                        double perSquareMetre = s.density() / 10_000 * field.density(sx, sz, h) / (SUB * SUB);
                        double[] shares = field.kindShares(sx, sz, h);
                        for (int k = 0; k < TreePlacement.KINDS; k++) {
                            kinds[k] += perSquareMetre * shares[k] * area[k];
                        }
                    }
                }
                double hidden = kinds[0] + kinds[1] + kinds[2];
                if (hidden <= 0) {
                    continue;
                }
                int o = (j * SIZE + i) * 4;
                for (int k = 0; k < TreePlacement.KINDS; k++) {
                    rgba[o + k] = (byte) Math.round(255 * kinds[k] / hidden);
                }
                rgba[o + 3] = (byte) Math.round(255 * (1 - Math.exp(-hidden)));
            }
        }
        return new Window(x, z, rgba);
    }

    /** The point congruent to {@code at} modulo the extent nearest {@code around}. */
    static double nearest(double at, double around) {
        double d = at - around;
        return around + d - EXTENT * Math.rint(d / EXTENT);
    }
}

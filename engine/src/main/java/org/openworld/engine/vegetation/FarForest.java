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
 * hiding {@code a_k} square metres from above (its impostor's top view, {@link ImpostorAtlas#topArea}, times the mean
 * square of its height, shrunk by the tree line's {@link PlacementField#stature} squared), the plants standing at
 * random, the ground left in view is the chance that no crown covers a point: {@code exp(−ρ Σ p_k a_k)} (a Poisson
 * count of crowns over the point). The canopy's colour mixes the kinds by {@code p_k a_k}.
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
                        double stature = field.stature(sx, sz, h);
                        for (int k = 0; k < TreePlacement.KINDS; k++) {
                            kinds[k] += perSquareMetre * shares[k] * area[k] * stature * stature;
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

    /**
     * Cells per side of the lattice the shapes' outlines are measured on, over ±1 plant height: 1.6 % of the height,
     * under a texel of the impostors' 64-texel frames, whose top view gives the same area within 1 %.
     */
    static final int GRID = 128;

    /**
     * A kind's outline seen from the side over its outline seen from above ({@link TreeShape}'s full shape at its
     * mean width, the side the mean of the views along x and along z). Seen at zenith angle θ a plant hides
     * {@code top · cos θ + side · sin θ} (exact for an upright cylinder), so it covers {@code top · (1 + ratio ·
     * tan θ)} of the ground behind it: a tall conifer hides far more of a forest's floor seen at a grazing angle than
     * its crown from above says ({@code shaders/common/forest.glsl}).
     */
    static double sideOverTop(TreeKind kind) {
        TreeShape.Geometry shape = TreeShape.of(kind, false);
        return (outline(shape, 0) + outline(shape, 2)) / 2 / outline(shape, 1);
    }

    /**
     * The area of a shape's outline seen along the axis (0 x, 1 y, 2 z), units of its height squared: its triangles
     * rasterised on a {@link #GRID}² lattice over ±1 heights, a cell counted when its centre lies in one.
     */
    static double outline(TreeShape.Geometry shape, int axis) {
        int u = axis == 0 ? 2 : 0;
        int w = axis == 1 ? 2 : 1;
        float[] v = shape.vertices();
        int[] t = shape.triangles();
        double cell = 2.0 / GRID;
        boolean[] covered = new boolean[GRID * GRID];
        for (int i = 0; i < t.length; i += 3) {
            double[] pu = new double[3];
            double[] pw = new double[3];
            for (int c = 0; c < 3; c++) {
                pu[c] = v[t[i + c] * TreeShape.FLOATS + u];
                pw[c] = v[t[i + c] * TreeShape.FLOATS + w];
            }
            int u0 = Math.max(0, (int) Math.floor((Math.min(pu[0], Math.min(pu[1], pu[2])) + 1) / cell));
            int u1 = Math.min(GRID - 1, (int) Math.floor((Math.max(pu[0], Math.max(pu[1], pu[2])) + 1) / cell));
            int w0 = Math.max(0, (int) Math.floor((Math.min(pw[0], Math.min(pw[1], pw[2])) + 1) / cell));
            int w1 = Math.min(GRID - 1, (int) Math.floor((Math.max(pw[0], Math.max(pw[1], pw[2])) + 1) / cell));
            double area = (pu[1] - pu[0]) * (pw[2] - pw[0]) - (pu[2] - pu[0]) * (pw[1] - pw[0]);
            if (area == 0) {
                continue;
            }
            for (int b = w0; b <= w1; b++) {
                for (int a = u0; a <= u1; a++) {
                    double x = (a + 0.5) * cell - 1;
                    double y = (b + 0.5) * cell - 1;
                    // the three edge functions share the triangle's sign inside it, whichever way it winds
                    double e0 = ((pu[1] - pu[0]) * (y - pw[0]) - (pw[1] - pw[0]) * (x - pu[0])) * area;
                    double e1 = ((pu[2] - pu[1]) * (y - pw[1]) - (pw[2] - pw[1]) * (x - pu[1])) * area;
                    double e2 = ((pu[0] - pu[2]) * (y - pw[2]) - (pw[0] - pw[2]) * (x - pu[2])) * area;
                    if (e0 >= 0 && e1 >= 0 && e2 >= 0) {
                        covered[b * GRID + a] = true;
                    }
                }
            }
        }
        int count = 0;
        for (boolean c : covered) {
            count += c ? 1 : 0;
        }
        return count * cell * cell;
    }

    /** The point congruent to {@code at} modulo the extent nearest {@code around}. */
    static double nearest(double at, double around) {
        double d = at - around;
        return around + d - EXTENT * Math.rint(d / EXTENT);
    }
}

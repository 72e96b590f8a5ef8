package org.openworld.engine.erosion;

import org.openworld.engine.drainage.FlowNetwork;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.HeightPyramid;

/**
 * Erodes a whole tile: the stream-power steady state on a coarse level, the finer detail laid back on top (the
 * package comment has the steps and why). Deterministic: the same map gives the same bits.
 */
public final class TileErosion {

    /** Spacing of the level the rivers are routed on, m: fine enough for valleys of a few hundred metres. */
    static final double ROUTING_SPACING_M = 8;
    /** Fewest samples per side of that level: below, a network has too few cells to branch. */
    private static final int MIN_ROUTING_SIZE = 64;
    /** Concavity m/n of the law: the middle of real channels' 0.35–0.6. */
    static final double THETA = 0.5;
    /**
     * Rounds of routing on the last surface and rebuilding it: the first follows the spectral relief's valleys, the
     * next ones let the rivers take the paths the carved relief gives them and the steepness settle so the highest
     * peak keeps its height (Hack's exponent of seed 1's tile rises from 0.44 to 0.48 over eight, then stays).
     */
    static final int ROUNDS = 8;
    /**
     * Uplift rises with the spectral height to this power, so ranges stand where the spectrum put its highs; a
     * square root rather than a steeper power, since uplift that grows with the height grows along the rivers too
     * and steepens their profiles' concavity (θ 0.62 at the power 1, 0.58 at ½ on seed 1's tile).
     */
    private static final double UPLIFT_POWER = 0.5;
    /**
     * Drainage area, m², at which the fine detail laid back is halved: a river bed is smooth where the hillslopes
     * around it are rough, and detail kept in full on a channel whose gradient is a few per cent would be steeper
     * than the river (at 10⁵ m², the smallest channel measured, a tenth of it is kept).
     */
    private static final double DETAIL_AREA_M2 = 1e4;
    /** Uplift of the lowest land, as a share of the highest's: the lowlands still slope to the sea. */
    private static final double UPLIFT_FLOOR = 0.05;

    private TileErosion() {
    }

    /**
     * The eroded map, of the same size, spacing and periodicity; the input is not changed.
     *
     * @param talusDegrees the steepest a hillslope stands (thermal erosion's angle of repose)
     */
    public static HeightMap erode(HeightMap base, double talusDegrees) {
        int k = routingLevel(base);
        HeightPyramid pyramid = HeightPyramid.build(base);
        HeightMap coarse = pyramid.level(k);
        int m = coarse.size();
        float[] original = coarse.heights();
        float peak = coarse.max();
        boolean[] sea = new boolean[m * m];
        float[] steepness = new float[m * m];
        for (int i = 0; i < original.length; i++) {
            sea[i] = original[i] <= 0;
            double n = Math.max(0, original[i]) / Math.max(peak, Float.MIN_NORMAL);
            steepness[i] = (float) (UPLIFT_FLOOR + (1 - UPLIFT_FLOOR) * Math.pow(n, UPLIFT_POWER));
        }
        // each round routes on the last surface, rebuilds it, and scales the steepness so the peak keeps its height
        double cap = Math.tan(Math.toRadians(talusDegrees));
        float[] z = original;
        FlowNetwork net = null;
        for (int round = 0; round < ROUNDS; round++) {
            net = network(coarse, z, sea);
            z = StreamPower.equilibrium(net, original, steepness, THETA, round == 0 ? Double.POSITIVE_INFINITY : cap);
            scale(steepness, peak / max(z));
        }
        Thermal.relax(z, m, coarse.spacing(), cap, coarse.periodic());
        float[] keep = new float[m * m];
        for (int i = 0; i < keep.length; i++) {
            keep[i] = (float) (1 / (1 + net.area(i) / DETAIL_AREA_M2));
        }
        return new HeightMap(base.size(), base.spacing(), withDetail(base, coarse, z, keep, k), base.periodic());
    }

    /** The level closest to {@link #ROUTING_SPACING_M}, no smaller than {@link #MIN_ROUTING_SIZE} samples. */
    public static int routingLevel(HeightMap base) {
        int k = (int) Math.max(0, Math.round(Math.log(ROUTING_SPACING_M / base.spacing()) / Math.log(2)));
        while (k > 0 && base.size() >> k < MIN_ROUTING_SIZE) {
            k--;
        }
        return k;
    }

    private static FlowNetwork network(HeightMap like, float[] z, boolean[] sea) {
        int m = like.size();
        return like.periodic() ? FlowNetwork.periodic(z, m, m, like.spacing(), like.spacing(), sea)
                : FlowNetwork.open(z, m, m, like.spacing(), like.spacing());
    }

    /**
     * Level 0 again: the eroded coarse heights read between their samples (bilinear), plus what the base has that
     * its coarse level has not, {@code base − coarse} read the same way, times the share {@code keep} (bilinear too).
     * Where erosion changed nothing and all is kept, the base comes back exactly.
     */
    private static float[] withDetail(HeightMap base, HeightMap coarse, float[] eroded, float[] keep, int k) {
        int n = base.size();
        float[] out = new float[n * n];
        float[] in = base.heights();
        HeightMap carved = new HeightMap(coarse.size(), coarse.spacing(), eroded, coarse.periodic());
        HeightMap kept = new HeightMap(coarse.size(), coarse.spacing(), keep, coarse.periodic());
        double step = 1.0 / (1 << k);
        for (int z = 0; z < n; z++) {
            for (int x = 0; x < n; x++) {
                double cx = x * step;
                double cz = z * step;
                double detail = in[z * n + x] - bilinear(coarse, cx, cz);
                out[z * n + x] = (float) (bilinear(carved, cx, cz) + bilinear(kept, cx, cz) * detail);
            }
        }
        return out;
    }

    private static double bilinear(HeightMap map, double gx, double gz) {
        int x0 = (int) Math.floor(gx);
        int z0 = (int) Math.floor(gz);
        double fx = gx - x0;
        double fz = gz - z0;
        double top = map.sample(x0, z0) * (1 - fx) + map.sample(x0 + 1, z0) * fx;
        double bottom = map.sample(x0, z0 + 1) * (1 - fx) + map.sample(x0 + 1, z0 + 1) * fx;
        return top * (1 - fz) + bottom * fz;
    }

    private static float max(float[] a) {
        float m = Float.NEGATIVE_INFINITY;
        for (float v : a) {
            m = Math.max(m, v);
        }
        return m;
    }

    private static void scale(float[] a, double factor) {
        for (int i = 0; i < a.length; i++) {
            a[i] *= (float) factor;
        }
    }
}

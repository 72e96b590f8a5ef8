package org.openworld.engine.erosion;

import org.openworld.engine.drainage.FlowNetwork;
import org.openworld.engine.terrain.heights.BandedHeights;

/**
 * Erodes one region of one level of the unbounded world: the stream-power steady state on the region's samples and
 * an apron around them, the coarser level's eroded rivers held as its base level (the package comment has the
 * cascade and why).
 */
final class RegionErosion {

    /** Samples routed beyond a region's support on each side, so its rivers know what lies past its edge. */
    static final int APRON = 32;
    /** Samples routed a side. */
    static final int ROUTED = ErodedWorld.SUPPORT + 2 * APRON;
    /**
     * A coarser level's cell whose drainage area is at least this many of its cells is a river the finer level
     * keeps as its base level: below it the finer level routes its own valleys.
     */
    static final double CHANNEL_CELLS = 4096;
    /**
     * Cells a channel of the level itself drains at least, to take a coarser river's area: the coarser river's
     * cells, read between its samples, lie in a band a few cells wide, and only the path this level's water takes
     * along it is the river (the rest would be a flat floor as wide as the coarsest level's cells).
     */
    static final double OWN_CHANNEL_CELLS = 8;
    /** Rounds of routing on the last surface and rebuilding it. */
    static final int ROUNDS = 2;
    /**
     * Channel steepness k_s = U/K where the uplift is highest, m: with θ = 0.5 a river draining 1 km² then falls
     * 15 % (a mountain stream), one draining 100 km² 1.5 %.
     */
    static final double STEEPNESS_M = 150;
    /** Uplift of the lowest land, as a share of the highest's: the lowlands still slope to their rivers. */
    private static final double UPLIFT_FLOOR = 0.05;

    private final BandedHeights plain;
    private final ErodedWorld world;
    private final double talus;
    private final double peak;

    /**
     * @param talusDegrees the steepest a hillslope stands
     * @param relief       the world's relief, m: the height at which the uplift is highest
     */
    RegionErosion(BandedHeights plain, ErodedWorld world, double talusDegrees, double relief) {
        this.plain = plain;
        this.world = world;
        this.talus = Math.tan(Math.toRadians(talusDegrees));
        this.peak = relief;
    }

    /** The region of level {@code level} whose core starts at its sample (rx · CORE, rz · CORE). */
    Region erode(int level, long rx, long rz) {
        int g = ROUTED;
        long ox = rx * ErodedWorld.CORE - ErodedWorld.OVERLAP - APRON;
        long oz = rz * ErodedWorld.CORE - ErodedWorld.OVERLAP - APRON;
        double d = plain.spacing(level);
        float[] bands = bands(level, ox, oz);
        float[] start = bands.clone();
        float[] base = new float[g * g]; // the heights the outlets keep
        float[] coarseArea = new float[g * g];
        boolean[] outlet = new boolean[g * g];
        if (level + 1 < plain.levels()) {
            coarser(level, ox, oz, bands, start, coarseArea);
        }
        float[] steepness = new float[g * g];
        for (int c = 0; c < steepness.length; c++) {
            outlet[c] = bands[c] <= 0; // the sea, the rivers' base level at 0 m; its floor is kept below
            base[c] = Math.max(0, start[c]);
            double n = Math.max(0, bands[c]) / peak;
            steepness[c] = (float) (STEEPNESS_M * (UPLIFT_FLOOR + (1 - UPLIFT_FLOOR) * Math.sqrt(Math.min(1, n))));
        }
        float[] z = start;
        float[] inflow = new float[g * g];
        FlowNetwork net = null;
        for (int round = 0; round < ROUNDS; round++) {
            net = FlowNetwork.open(z, g, g, d, d, outlet);
            for (int c = 0; c < inflow.length; c++) { // a coarse river's area goes to this level's channels only
                inflow[c] = net.area(c) >= OWN_CHANNEL_CELLS * d * d ? coarseArea[c] : 0;
            }
            z = StreamPower.equilibrium(net, base, steepness, inflow, TileErosion.THETA, talus);
        }
        for (int c = 0; c < z.length; c++) {
            z[c] = outlet[c] ? bands[c] : z[c];
        }
        Thermal.relax(z, g, d, talus, false);
        int s = ErodedWorld.SUPPORT;
        float[] delta = new float[s * s];
        float[] area = new float[s * s];
        for (int j = 0; j < s; j++) {
            for (int i = 0; i < s; i++) {
                int c = (j + APRON) * g + i + APRON;
                delta[j * s + i] = z[c] - bands[c];
                area[j * s + i] = (float) Math.max(net.area(c), inflow[c]);
            }
        }
        return new Region(delta, area);
    }

    /**
     * The plain bands over a region's routed samples, made on this thread in windows too small for
     * {@link BandedHeights#level} to share out: a thread of a parallel stream that waits for its rows may run
     * another task meanwhile, and one that asks for a region this thread is making would wait for itself.
     */
    private float[] bands(int level, long ox, long oz) {
        int g = ROUTED;
        int half = (g + 1) / 2;
        float[] out = new float[g * g];
        for (int b = 0; b < 2; b++) {
            for (int a = 0; a < 2; a++) {
                float[] part = plain.level(level, ox + a * half, oz + b * half, half);
                for (int j = 0; j < half && b * half + j < g; j++) {
                    int w = Math.min(half, g - a * half);
                    System.arraycopy(part, j * half, out, (b * half + j) * g + a * half, w);
                }
            }
        }
        return out;
    }

    /**
     * What the next coarser level, already eroded, gives a region: the start surface (these bands plus its
     * displacement, read bilinearly), and the drainage area of its rivers, those draining {@value #CHANNEL_CELLS} of
     * its cells or more, which the finer level's cells along them take as their own.
     */
    private void coarser(int level, long ox, long oz, float[] bands, float[] start, float[] coarseArea) {
        int g = ROUTED;
        long cx = Math.floorDiv(ox, 2);
        long cz = Math.floorDiv(oz, 2);
        int m = g / 2 + 3;
        float[][] moved = world.blend(level + 1, cx, cz, m, m);
        double channel = CHANNEL_CELLS * Math.pow(plain.spacing(level + 1), 2);
        for (int j = 0; j < g; j++) {
            double gz = (oz + j) / 2.0 - cz;
            int cj = (int) Math.floor(gz);
            for (int i = 0; i < g; i++) {
                double gx = (ox + i) / 2.0 - cx;
                int ci = (int) Math.floor(gx);
                int c = j * g + i;
                start[c] = (float) (bands[c] + ErodedWorld.bilinear(moved[0], m, ci, cj, gx - ci, gz - cj));
                double area = ErodedWorld.bilinear(moved[1], m, ci, cj, gx - ci, gz - cj);
                coarseArea[c] = area >= channel ? (float) area : 0;
            }
        }
    }
}

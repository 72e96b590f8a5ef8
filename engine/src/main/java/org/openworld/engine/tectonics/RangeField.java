package org.openworld.engine.tectonics;

/**
 * Where the unbounded world has mountain ranges and where plains: a field smoother than any of its height bands (the
 * package comment has the formula and the reasons for its numbers). A pure function of the position and the seed,
 * so every block of every level gets the same value at a place, whatever order they are made in.
 */
public final class RangeField {

    /** Lattice spacing of the coarse octave, m: ranges and plains some 15–40 km across. */
    static final double COARSE_M = 32_000;
    /** The fine octave: half the spacing, half the weight, turned so the two lattices do not line up. */
    static final double FINE_M = COARSE_M / 2;
    private static final double FINE_WEIGHT = 0.5;
    private static final double FINE_ANGLE = 0.6; // radians
    /** Field values at which the plains end and the ranges begin (the field lies mostly within ±0.6). */
    static final double PLAINS_BELOW = -0.3;
    static final double RANGES_ABOVE = 0.1;
    /** The relief a plain keeps, as a share of a range's. */
    static final double PLAIN_RELIEF = 0.2;
    /** How far a plain's mean lies below a range's, as a share of the world's relief: lowlands, not plateaus. */
    static final double PLAIN_DROP = 0.25;

    private final long seed;
    private final double drop;

    /**
     * @param seed   the world's seed
     * @param relief the world's relief, m (terrain.relief)
     */
    public RangeField(int seed, double relief) {
        this.seed = mix(seed ^ 0x7EC7_0A1C_5EEDL);
        this.drop = PLAIN_DROP * relief;
    }

    /** How far below the world's mean a plain's mean lies, m: the most this field lowers any height. */
    public double drop() {
        return drop;
    }

    /** The share of the bands' relief kept at (x, z): {@link #PLAIN_RELIEF} on the plains, 1 in the ranges. */
    public double amplitude(double x, double z) {
        double t = (field(x, z) - PLAINS_BELOW) / (RANGES_ABOVE - PLAINS_BELOW);
        t = Math.max(0, Math.min(1, t));
        double s = t * t * (3 - 2 * t);
        return PLAIN_RELIEF + (1 - PLAIN_RELIEF) * s;
    }

    /** The height at (x, z) made of the bands' sum there: {@code −drop · (1 − a) + a · bands}, metres off the mean. */
    public double shape(double x, double z, double bands) {
        double a = amplitude(x, z);
        return -drop * (1 - a) + a * bands;
    }

    /** Two octaves of value noise, each in [−1, 1], weighted 1 and ½, divided by 1.5. */
    double field(double x, double z) {
        double c = StrictMath.cos(FINE_ANGLE);
        double s = StrictMath.sin(FINE_ANGLE);
        double coarse = valueNoise(x / COARSE_M, z / COARSE_M, seed);
        double fine = valueNoise((c * x - s * z) / FINE_M, (s * x + c * z) / FINE_M, seed + 1);
        return (coarse + FINE_WEIGHT * fine) / (1 + FINE_WEIGHT);
    }

    /** Random values in [−1, 1] on the integer lattice, joined by the quintic fade (C² across cells). */
    private static double valueNoise(double u, double v, long seed) {
        double fu = Math.floor(u);
        double fv = Math.floor(v);
        long iu = (long) fu;
        long iv = (long) fv;
        double tu = fade(u - fu);
        double tv = fade(v - fv);
        double a = lattice(iu, iv, seed);
        double b = lattice(iu + 1, iv, seed);
        double c = lattice(iu, iv + 1, seed);
        double d = lattice(iu + 1, iv + 1, seed);
        return (a + tu * (b - a)) * (1 - tv) + (c + tu * (d - c)) * tv;
    }

    private static double fade(double t) {
        return t * t * t * (t * (6 * t - 15) + 10);
    }

    private static double lattice(long iu, long iv, long seed) {
        long h = mix(seed ^ mix(iu * 0x9E37_79B9_7F4A_7C15L ^ mix(iv * 0xC2B2_AE3D_27D4_EB4FL)));
        return (h >>> 11) * 0x1.0p-53 * 2 - 1;
    }

    /** SplittableRandom's 64-bit finaliser (Stafford's variant 13): every input bit reaches every output bit. */
    private static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58_476D_1CE4_E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D0_49BB_1331_11EBL;
        return z ^ (z >>> 31);
    }
}

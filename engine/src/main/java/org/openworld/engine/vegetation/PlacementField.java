package org.openworld.engine.vegetation;

import org.openworld.engine.core.HeightField;
import org.openworld.engine.environment.Moisture;

/**
 * How thickly plants grow anywhere, and which kind, from the land alone: no GL, no state but the seed, so any point
 * gives the same answer whichever block of the world is placed first and on whichever thread.
 *
 * <p><b>The density</b>, 0 to 1 (a share of {@code vegetation.density}), is a product of four factors:
 * <pre>
 *   density  = patches(x, z) · min(1, 0.5 + moisture) · treeline(x, z, h)
 *   patches  = FLOOR + (1 − FLOOR) · smoothstep(EDGE_LOW, EDGE_HIGH, 0.65 · n(x / 600 m) + 0.35 · n(x / 150 m))
 *   treeline = (1 − snow(h)) · (1 − smoothstep(line − band · (1 + ASPECT · shade), line, h))
 *   band     = TREELINE_SHARE · (line − shore), or TREELINE_BAND without water
 * </pre>
 * {@code n} is value noise from the seed (a smooth cubic between hashed lattice values): the sum wanders over a few
 * hundred metres, and the narrow smoothstep turns it into forests with edges, clearings and groves rather than a
 * uniform scatter; {@link #FLOOR} keeps a few lone plants in the open.
 *
 * Neutral ground (moisture 0.5) grows the full forest; a dry ridge half of it.
 *
 * <p><b>The tree line</b> ({@link TreePlacement.Limits#highest}) lies half-way up the snow line's fringe, where snow
 * is as likely as not; {@code snow(h)} is that chance ({@link org.openworld.engine.environment.SnowLine#chanceAt}),
 * so the forest already thins where snow lies in patches, and over the band below the line it thins to nothing.
 * {@code shade}, −1 to 1, is how steeply the slope faces away from the sun (north), as a share of a 30° slope: a
 * shaded slope's forest thins over a band half again as deep, a sun-facing slope's keeps its trees up to half the
 * band below the line, as real tree lines stand higher on the sunny side of a valley. Towards the line the trees
 * also shrink ({@link #stature}, down to {@link #MIN_STATURE} of their height) and give way to bushes
 * ({@link #KRUMMHOLZ}).
 *
 * <p><b>Moisture</b> is the world's {@link Moisture} where one is published (the seam a flow field feeds). Without
 * one, the stand-in is the land's shape: wet near the water (falling off over {@link #SHORE_RANGE} of height), wet in
 * hollows (the ground {@link #PROBE} m around is higher: the Laplacian, water's way of gathering), dry on slopes that
 * face the sun (south, +z, here in the northern hemisphere) by their steepness.
 *
 * <p><b>The kind</b>: bushes where the forest thins (its edges, the open and the tree line); of the trees, broadleaf
 * below {@link #ZONE_LOW} of the way from the shore to the tree line, conifers above {@link #ZONE_HIGH}, mixed
 * between, the zones moved down on dry ground and up on wet ({@link #ZONE_MOISTURE}): beech and oak in the valleys,
 * spruce and fir on the upper slopes, as in the Alps. Each kind is chosen with those odds from a uniform number the
 * caller draws.
 *
 * <p>The vegetation publishes its field as a world resource, so what grows under the trees (the grass) thickens and
 * thins with the same land: {@link #ground} is the field without the forest's patches and the tree line.
 */
public final class PlacementField {

    /** Wavelengths of the two noise octaves, metres: forests a few hundred metres across, groves inside them. */
    static final double PATCH = 600;
    static final double GROVE = 150;
    /** The noise values over which the density goes from the open to the forest: a narrow band, sharp edges. */
    static final double EDGE_LOW = 0.42;
    static final double EDGE_HIGH = 0.55;
    /** The open's share of the forest's density: a lone tree or bush here and there. */
    static final double FLOOR = 0.06;
    /**
     * The tree line's band: forests thin to nothing over the top quarter of the heights between the shore and the
     * tree line (a world's relief sets where its trees stop, as the climate does on Earth), or over 250 m below the
     * line where there is no water to measure from.
     */
    static final double TREELINE_SHARE = 0.25;
    static final double TREELINE_BAND = 250;
    /** How much the slope's aspect deepens (shade) or narrows (sun) the tree line's band: half of it either way. */
    static final double ASPECT = 0.5;
    /** Gradient (rise over run) of a slope that counts as fully sun-facing or shaded: tan 30°, the default limit. */
    static final double ASPECT_FULL = 0.577;
    /** The height of a tree at the tree line, as a share of its height lower down: stunted, wind-bent trees. */
    static final double MIN_STATURE = 0.5;
    /** The share of the trees that bushes take at the tree line (krummholz, dwarf pine), growing into it. */
    static final double KRUMMHOLZ = 0.6;
    /**
     * The zones, as shares of the way from the shore to the tree line: broadleaf trees alone below ZONE_LOW,
     * conifers alone above ZONE_HIGH; ZONE_MOISTURE moves them by the moisture's distance from neutral (0.5).
     */
    static final double ZONE_LOW = 0.3;
    static final double ZONE_HIGH = 0.6;
    static final double ZONE_MOISTURE = 0.3;
    /** Metres of height above the water over which the shore's wetness fades. */
    static final double SHORE_RANGE = 40;
    /** Metres to the four points around a foot whose mean height tells a hollow from a ridge. */
    static final double PROBE = 24;

    private final HeightField heights;
    private final Moisture moisture;
    private final TreePlacement.Limits limits;
    private final long seed;

    /** {@code moisture} null: the stand-in from the land's shape. */
    PlacementField(HeightField heights, Moisture moisture, TreePlacement.Limits limits, int seed) {
        this.heights = heights;
        this.moisture = moisture;
        this.limits = limits;
        this.seed = TreePlacement.mix(seed ^ 0x5EED_F0E5L);
    }

    /** The density at (x, z) on ground of height {@code h}, 0 to 1. */
    double density(double x, double z, double h) {
        return patches(x, z) * ground(x, z, h) * treeline(x, z, h);
    }

    /** A plant's height at (x, z) as a share of its height below the tree line: {@link #MIN_STATURE} to 1. */
    double stature(double x, double z, double h) {
        return MIN_STATURE + (1 - MIN_STATURE) * treeline(x, z, h);
    }

    /**
     * What the land grows at (x, z) on ground of height {@code h}, 0 to 1, as the moisture allows:
     * {@code min(1, 0.5 + moisture)}, the density without the forest's patches and the tree line (grass grows above
     * the trees).
     */
    public double ground(double x, double z, double h) {
        return Math.min(1, 0.5 + moisture(x, z, h));
    }

    /** Forest or open: {@link #FLOOR} to 1. */
    double patches(double x, double z) {
        double n = 0.65 * noise(x / PATCH, z / PATCH, 0) + 0.35 * noise(x / GROVE, z / GROVE, 1);
        return FLOOR + (1 - FLOOR) * smoothstep(EDGE_LOW, EDGE_HIGH, n);
    }

    /** The tree line's factor: 1 well below it, 0 at it and above; see the class's formula. */
    double treeline(double x, double z, double h) {
        double line = limits.highest();
        if (Double.isInfinite(line)) {
            return 1;
        }
        double band = Double.isInfinite(limits.lowest()) ? TREELINE_BAND
                : TREELINE_SHARE * Math.max(0, line - limits.lowest());
        double snowless = 1 - limits.snowChance(h);
        if (h <= line - (1 + ASPECT) * band) {
            return snowless; // below the deepest band: no need for the slope's aspect
        }
        double shade = Math.max(-1, Math.min(1, -sunward(x, z) / ASPECT_FULL));
        return snowless * (1 - smoothstep(line - band * (1 + ASPECT * shade), line, h));
    }

    /** The slope's fall towards the sun (south, +z) over {@link #PROBE} either side: positive facing the sun. */
    private double sunward(double x, double z) {
        return (heights.heightAt(x, z - PROBE) - heights.heightAt(x, z + PROBE)) / (2 * PROBE);
    }

    /** The world's moisture, or the stand-in: shore, hollows, sunward slopes. */
    double moisture(double x, double z, double h) {
        if (moisture != null) {
            return Math.min(1, Math.max(0, moisture.at(x, z)));
        }
        double shore = Double.isInfinite(limits.lowest()) ? 0 : Math.exp(-Math.max(0, h - limits.lowest()) / SHORE_RANGE);
        double n = heights.heightAt(x, z - PROBE);
        double s = heights.heightAt(x, z + PROBE);
        double hollow = (n + s + heights.heightAt(x - PROBE, z) + heights.heightAt(x + PROBE, z)) / 4 - h;
        // the slope's fall towards the south (+z) over the run: positive on a sun-facing slope (sunward's, from the
        // two probes already read)
        double sunward = Math.max(0, (n - s) / (2 * PROBE));
        return Math.min(1, Math.max(0, 0.5 + 0.5 * shore + 4 * hollow / PROBE - 1.5 * sunward));
    }

    /** The kind of plant at a place of this density and height, from a uniform number {@code u} in [0, 1). */
    TreeKind kind(double x, double z, double h, double u) {
        double[] shares = kindShares(x, z, h);
        // bushes first, then broadleaf trees, then conifers along u
        int bush = TreeKind.BUSH.ordinal();
        int broadleaf = TreeKind.BROADLEAF.ordinal();
        return u < shares[bush] ? TreeKind.BUSH : u < shares[bush] + shares[broadleaf] ? TreeKind.BROADLEAF
                : TreeKind.CONIFER;
    }

    /**
     * Each kind's share of the plants at a place, in {@link TreeKind} order, summing to 1: bushes {@code 0.15 + 0.7 ·
     * open}, growing by {@link #KRUMMHOLZ} of the rest towards the tree line; of the trees, broadleaf by the zones
     * {@code 1 − smoothstep(ZONE_LOW, ZONE_HIGH, up + ZONE_MOISTURE · (0.5 − moisture))}, {@code up} the share of the
     * way from the shore to the tree line (a half where either is missing).
     */
    double[] kindShares(double x, double z, double h) {
        double open = 1 - (patches(x, z) - FLOOR) / (1 - FLOOR);
        double bush = 0.15 + 0.7 * open;
        bush += (1 - bush) * KRUMMHOLZ * (1 - treeline(x, z, h));
        double up = Double.isInfinite(limits.highest()) || Double.isInfinite(limits.lowest()) ? 0.5
                : (h - limits.lowest()) / Math.max(1, limits.highest() - limits.lowest());
        double broadleaf = (1 - bush)
                * (1 - smoothstep(ZONE_LOW, ZONE_HIGH, up + ZONE_MOISTURE * (0.5 - moisture(x, z, h))));
        return new double[] {1 - bush - broadleaf, broadleaf, bush};
    }

    /** Value noise, 0 to 1: hashed values on the integer lattice, blended by a smooth cubic. */
    private double noise(double x, double z, int octave) {
        long ix = (long) Math.floor(x);
        long iz = (long) Math.floor(z);
        double fx = x - ix;
        double fz = z - iz;
        double sx = fx * fx * (3 - 2 * fx);
        double sz = fz * fz * (3 - 2 * fz);
        double a = lattice(ix, iz, octave);
        double b = lattice(ix + 1, iz, octave);
        double c = lattice(ix, iz + 1, octave);
        double d = lattice(ix + 1, iz + 1, octave);
        return (a + (b - a) * sx) * (1 - sz) + (c + (d - c) * sx) * sz;
    }

    private double lattice(long ix, long iz, int octave) {
        return (TreePlacement.mix(TreePlacement.mix(TreePlacement.mix(seed + octave) ^ ix) ^ iz) >>> 11) * 0x1.0p-53;
    }

    static double smoothstep(double e0, double e1, double v) {
        if (e1 <= e0) {
            return v < e0 ? 0 : 1;
        }
        double t = Math.min(1, Math.max(0, (v - e0) / (e1 - e0)));
        return t * t * (3 - 2 * t);
    }
}

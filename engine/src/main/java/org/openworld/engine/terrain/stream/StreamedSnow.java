package org.openworld.engine.terrain.stream;

import java.util.SplittableRandom;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.material.SnowMap;
import org.openworld.engine.terrain.material.TerrainMaps;

/**
 * The unbounded world's snow map (paper 2.2, as {@link SnowMap} makes it for a tile), made block by block as the
 * clipmap streams ({@link UnboundedWorld}): each block of level 0 gets the tile's probabilistic snow, its opening and
 * closing and its blur; coarser levels get what that snow averages to.
 *
 * <p><b>Level 0.</b> A sample is snow when a uniform number u is below p(n) ({@link SnowMap#probability}, n the
 * normalised height h / relief + seaFraction). Unlike the tile's row-seeded stream, u is a hash of the seed and the
 * world sample's index, so a sample's chance is its place's whatever block made it. The opening and closing of
 * radius r ({@code terrain.snow-morphology}) and the blur ({@link TerrainMaps#SNOW_BLUR_PASSES} binomial passes)
 * reach {@link #border} samples, which the block carries around it: its interior is then what one map over the
 * whole world would hold there, and blocks join without a seam.
 *
 * <p><b>Coarser levels.</b> A level-L texel stands for 4^L level-0 samples, so it shows their expected snow: the
 * share c(p) of a field of chance p that the opening and closing leave as snow. c is measured once, when the world is
 * made, on a random field per p (the opening keeps only what fills a (2r + 1)² square, so c(p) stays near 0 until p
 * nears 1: c(0.9) is about 0.5 for r = 1), and read with p(n) of the level's own height. The speckle of level 0 gives
 * way to its mean where patches change from level 0 to 1, which is where the tile's mips make the same change.
 *
 * <p><b>Cost.</b> A level-0 block: its (block + 2 · border)² samples hashed, four sliding-count passes and six
 * binomial ones, 0.35–0.55 ms for 64² on the GL thread (one core of a 2-core machine); a coarser block, one table
 * lookup a sample, 0.08 ms.
 * Limits: level 0 is the only level with the ragged fringe; coarser levels show its mean, a smooth ramp.
 */
final class StreamedSnow {

    /** Steps of p at which c(p) is measured (and linearly interpolated between). */
    static final int TABLE_STEPS = 16;
    /** Side of the random field c(p) is measured on, samples. */
    private static final int TABLE_FIELD = 128;
    /** Distinguishes the snow's hash from the other users of the world seed. */
    private static final long STREAM = 0x5EED_5A0E_0000_0003L;

    private final TerrainSettings settings;
    private final long seed;
    private final float[] expected;

    /** The snow of this world's settings and seed, its table c(p) measured now. */
    StreamedSnow(TerrainSettings settings, int seed) {
        this.settings = settings;
        this.seed = seed ^ STREAM;
        this.expected = new float[TABLE_STEPS + 1];
        SplittableRandom random = new SplittableRandom(this.seed);
        byte[] field = new byte[TABLE_FIELD * TABLE_FIELD];
        for (int k = 0; k <= TABLE_STEPS; k++) {
            double p = (double) k / TABLE_STEPS;
            for (int i = 0; i < field.length; i++) {
                field[i] = random.nextDouble() < p ? SnowMap.SNOW : 0;
            }
            SnowMap.openAndClose(field, TABLE_FIELD, settings.snowMorphology(), true);
            long snow = 0;
            for (byte b : field) {
                snow += b != 0 ? 1 : 0;
            }
            expected[k] = (float) snow / field.length;
        }
        // c never falls as p rises (more snow in never means less snow out: the opening and the closing are both
        // monotone), but the measured shares near 0 carry the draw's luck: keep each at least its predecessor
        for (int k = 1; k <= TABLE_STEPS; k++) {
            expected[k] = Math.max(expected[k], expected[k - 1]);
        }
    }

    /** Samples of border a level-0 block needs: 4r for the opening and closing, two per blur pass. */
    static int border(TerrainSettings settings) {
        return 4 * settings.snowMorphology() + 2 * TerrainMaps.SNOW_BLUR_PASSES;
    }

    /** c(p): the share of a field of chance p that the opening and closing leave as snow. */
    double expectedCoverage(double p) {
        double at = Math.max(0, Math.min(1, p)) * TABLE_STEPS;
        int k = Math.min(TABLE_STEPS - 1, (int) at);
        return expected[k] + (at - k) * (expected[k + 1] - expected[k]);
    }

    /** The snow a coarse level shows at this height, metres: c(p) of the chance p there. */
    double coverageAt(double height) {
        return expectedCoverage(probability((float) height));
    }

    /**
     * A block's snow, 0..255 per sample, row-major: level {@code level}'s samples (ix0 .. ix0 + block − 1) × (iz0 ..),
     * from its heights given with a border of {@code border} samples (at least {@link #border} for level 0).
     */
    byte[] block(int level, long ix0, long iz0, int block, float[] bordered, int border) {
        int side = block + 2 * border;
        byte[] out = new byte[block * block];
        if (level > 0) {
            for (int j = 0; j < block; j++) {
                for (int i = 0; i < block; i++) {
                    double c = expectedCoverage(probability(bordered[(j + border) * side + i + border]));
                    out[j * block + i] = (byte) Math.round(255 * c);
                }
            }
            return out;
        }
        if (border < border(settings)) {
            throw new IllegalArgumentException("level 0's snow needs a border of " + border(settings)
                    + " samples, got " + border);
        }
        byte[] snow = new byte[side * side];
        for (int j = 0; j < side; j++) {
            for (int i = 0; i < side; i++) {
                double u = uniform(ix0 - border + i, iz0 - border + j);
                snow[j * side + i] = u < probability(bordered[j * side + i]) ? SnowMap.SNOW : 0;
            }
        }
        SnowMap.openAndClose(snow, side, settings.snowMorphology(), false);
        byte[] soft = TerrainMaps.blur(snow, side, false);
        for (int j = 0; j < block; j++) {
            System.arraycopy(soft, (j + border) * side + border, out, j * block, block);
        }
        return out;
    }

    private double probability(float height) {
        return SnowMap.probability(height / settings.relief() + settings.seaFraction(), settings);
    }

    /** A uniform number in [0, 1) for a level-0 sample: its index and the seed, mixed (SplitMix64's finaliser). */
    private double uniform(long ix, long iz) {
        long z = seed + ix * 0x9E37_79B9_7F4A_7C15L + iz * 0xC2B2_AE3D_27D4_EB4FL;
        z = (z ^ (z >>> 30)) * 0xBF58_476D_1CE4_E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D0_49BB_1331_11EBL;
        z ^= z >>> 31;
        return (z >>> 11) * 0x1.0p-53;
    }
}

package org.openworld.engine.terrain.stream;

import java.util.SplittableRandom;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.material.SnowMap;
import org.openworld.engine.terrain.material.TerrainMaps;

/**
 * The unbounded world's snow map (paper 2.2), made block by block as the clipmap streams ({@link UnboundedWorld}):
 * each block of level 0 gets the snow every height source gets ({@link SnowMap#cover}) and the tile's blur; coarser
 * levels get what that snow averages to.
 *
 * <p><b>Level 0.</b> {@link SnowMap#cover} over the block and its border: a sample's random draw is a hash of its
 * place, whatever block made it. The opening and closing of radius r ({@code terrain.snow-morphology}) and the blur
 * ({@link TerrainMaps#SNOW_BLUR_PASSES} binomial passes) reach {@link #border} samples, which the block carries
 * around it: its interior is then what one map over the whole world would hold there, and blocks join without a
 * seam.
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
    /** Distinguishes the table's random fields from the other users of the world seed. */
    private static final long STREAM = 0x5EED_5A0E_0000_0003L;

    private final TerrainSettings settings;
    private final int seed;
    private final float[] expected;

    /** The snow of this world's settings and seed, its table c(p) measured now. */
    StreamedSnow(TerrainSettings settings, int seed) {
        this.settings = settings;
        this.seed = seed;
        this.expected = new float[TABLE_STEPS + 1];
        SplittableRandom random = new SplittableRandom(seed ^ STREAM);
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
        byte[] snow = SnowMap.cover(bordered, side, ix0 - border, iz0 - border, 0, settings, seed);
        byte[] soft = TerrainMaps.blur(snow, side, false);
        for (int j = 0; j < block; j++) {
            System.arraycopy(soft, (j + border) * side + border, out, j * block, block);
        }
        return out;
    }

    private double probability(float height) {
        return SnowMap.probability(height / settings.relief() + settings.seaFraction(), settings);
    }
}

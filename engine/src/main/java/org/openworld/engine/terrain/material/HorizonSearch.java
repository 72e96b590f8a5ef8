package org.openworld.engine.terrain.material;

import java.util.List;
import java.util.function.IntToDoubleFunction;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Uniform;

/**
 * How much of its sky each place of the ground sees (the light in the shadows): horizon-based ambient occlusion
 * from the heights, made on the GPU by {@code shaders/terrain/material/horizon.glsl} for the samples of one level
 * at a time, the tile's ({@link TileSky}) or a streamed block's ({@code stream.StreamedSky}). This class holds the search's
 * parameters, which both set as uniforms.
 *
 * <p>Along each of {@value #DIRECTIONS} azimuths φ the horizon is the highest elevation at which the ground is seen,
 * {@code tan h_φ = max_r (H(p + r·φ) − H(p)) / r}, over distances r growing by {@value #STEP_GROWTH} from one sample
 * to {@value #REACH_METRES} m, each read from the level whose samples lie about {@code r / 4} apart (a far peak needs
 * no fine level, and the low-passed level does not alias). The ground's own slope hides nothing that the sky light
 * does not already leave out for a tilted normal, so only what rises above the tangent plane counts: the excess
 * angle {@code α_φ = max(0, h_φ − t_φ)}, t_φ the plane's elevation along φ. In one azimuth the sky between
 * elevations α and 90° gives the share {@code ∫_α^{π/2} sin e cos e de / ∫_0^{π/2} sin e cos e de = cos² α} of a
 * horizontal surface's irradiance from that azimuth (the cosine of incidence times the solid angle's cos e), so
 * <pre>  V = (1/N) Σ_φ cos² α_φ</pre>
 * is 1 on open ground and on a plain slope, about 0.75 at the foot of a long vertical wall, and lower down a narrow
 * gorge. The material shades with {@code V · E_sky(n) + (1 − V) · E_hidden}: the hidden sky replaced by the light
 * of the terrain that hides it, {@code E_hidden = albedo · (E_sun · sin(elevation) / 2 + E_up)} (the sky system's
 * reckoning: terrain lit by the sky and, since half of what surrounds a place faces the sun, by half the sun).
 *
 * <p>Cost: {@code N · log(R/d) / log(growth)} bilinear lookups per sample (8 × 19 at 8 m). Limits: eight azimuths
 * miss a narrow notch between them; the tangent plane stands in for the hemisphere of a tilted surface (exact for a
 * horizontal one); the sky is taken as uniform, so a wall hiding the sun's bright side of the sky darkens as much as
 * one hiding the dim side; the occluder's light is the same everywhere, so the shadowed face of the wall that casts
 * a shadow counts as half sunlit.
 */
public final class HorizonSearch {

    /** Azimuths at which the horizon is found. */
    public static final int DIRECTIONS = 8;
    /** How far the horizon is searched, metres: beyond, a 1 km mountain stands under 20° and hides little. */
    public static final double REACH_METRES = 3000;
    /** Ratio of consecutive search distances. */
    public static final double STEP_GROWTH = 1.4;
    /** Samples of the level read at distance r are at most r / LEVEL_SPAN apart. */
    private static final double LEVEL_SPAN = 4;

    private HorizonSearch() {
    }

    /**
     * The distances at which the horizon is searched from a grid of samples {@code d} metres apart:
     * {@code d · STEP_GROWTH^j} for j = 0, 1, ... while under {@link #REACH_METRES}, and the first beyond.
     */
    public static double[] distances(double d) {
        int steps = Math.max(0, (int) Math.ceil(Math.log(REACH_METRES / d) / Math.log(STEP_GROWTH)) + 1);
        double[] r = new double[steps];
        for (int j = 0; j < steps; j++) {
            r[j] = d * Math.pow(STEP_GROWTH, j);
        }
        return r;
    }

    /**
     * The level read at distance {@code r}: from {@code from}, the coarsest of the {@code count} levels whose samples
     * lie at most {@code r / LEVEL_SPAN} apart ({@code spacing} gives a level's, growing with the level).
     */
    public static int levelAt(double r, int from, int count, IntToDoubleFunction spacing) {
        int k = from;
        while (k + 1 < count && spacing.applyAsDouble(k + 1) <= r / LEVEL_SPAN) {
            k++;
        }
        return k;
    }

    /** The defines of a program that searches from levels no finer than samples {@code finest} metres apart. */
    public static List<String> defines(double finest) {
        return List.of("SKY_DIRECTIONS " + DIRECTIONS, "SKY_STEPS " + Math.max(1, distances(finest).length));
    }

    /** The search's uniforms in a program that includes {@code terrain/material/horizon.glsl}. */
    public static final class Uniforms {
        private final Uniform.Int level;
        private final Uniform.Int steps;
        private final Uniform.Float[] searchDistance;
        private final Uniform.Int[] searchLevel;

        /**
         * Sets the levels and level 0's spacing now; {@code finest} as in {@link #defines}.
         */
        public Uniforms(ShaderProgram program, int levels, double spacing0, double finest) {
            program.int1("levels").set(levels);
            program.float1("spacing0").set((float) spacing0);
            level = program.int1("level");
            steps = program.int1("steps");
            int most = Math.max(1, distances(finest).length);
            searchDistance = new Uniform.Float[most];
            searchLevel = new Uniform.Int[most];
            for (int j = 0; j < most; j++) {
                searchDistance[j] = program.float1("searchDistance[" + j + "]");
                searchLevel[j] = program.int1("searchLevel[" + j + "]");
            }
        }

        /**
         * The search from level {@code l} of {@code count} levels, {@code spacing} giving a level's, metres; the
         * program in use.
         */
        public void set(int l, int count, IntToDoubleFunction spacing) {
            level.set(l);
            double[] distances = distances(spacing.applyAsDouble(l));
            steps.set(distances.length);
            for (int j = 0; j < distances.length; j++) {
                searchDistance[j].set((float) distances[j]);
                searchLevel[j].set(levelAt(distances[j], l, count, spacing));
            }
        }
    }
}

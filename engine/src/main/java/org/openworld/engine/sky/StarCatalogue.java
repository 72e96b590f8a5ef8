package org.openworld.engine.sky;

import java.util.SplittableRandom;

/**
 * The stars, synthesised at start rather than read from a table: every star the eye sees on a dark night, placed at
 * random on the celestial sphere (uniform in right ascension and in the sine of the declination) with magnitudes that
 * follow the counts of the real sky.
 *
 * <p>The star-count law: the number of stars brighter than magnitude m over the whole sky is
 * {@code N(<m) = 10^(A + S·m)}, A = {@value #COUNT_AT_ZERO}, S = {@value #COUNT_SLOPE}, a straight line through Allen's
 * counts (Astrophysical Quantities: about 13 stars brighter than 1, 170 than 3, 4800 than 6). Down to the naked eye's
 * limit m = {@value #LIMIT} that is 4570 stars; the brightest drawn, at N = ½, has m = −1.8 (Sirius: −1.46).
 * Magnitudes are drawn stratified: the i-th brightest of n has N(<m) = i + ½, m = (log10(i + ½) − A) / S, so the
 * counts follow the law exactly and only the positions are random. A star of magnitude m gives 10^(−0.4 (m − V☉))
 * of the sun's light ({@link MoonPosition#SUN_MAGNITUDE}); a star of magnitude 0 about 2·10⁻¹¹.
 *
 * <p>Limits: no clustering along the Milky Way, no colours (the rods see none, and the night's picture is theirs),
 * and no real constellations.
 *
 * @param directions unit vectors in equatorial axes (x towards right ascension 0, z the north pole), 3 per star
 * @param irradiance each star's light against the sun's (display units), brightest first
 */
public record StarCatalogue(float[] directions, float[] irradiance) {

    /** log10 of the whole sky's count of stars brighter than magnitude 0. */
    static final double COUNT_AT_ZERO = 0.6;
    /** The count's growth, decades per magnitude. */
    static final double COUNT_SLOPE = 0.51;
    /** The faintest magnitude the eye sees on a dark night. */
    static final double LIMIT = 6;

    /** Every star brighter than {@link #LIMIT}, placed by {@code seed}. */
    public static StarCatalogue generate(long seed) {
        int n = (int) Math.floor(Math.pow(10, COUNT_AT_ZERO + COUNT_SLOPE * LIMIT) - 0.5);
        SplittableRandom random = new SplittableRandom(seed);
        float[] directions = new float[3 * n];
        float[] irradiance = new float[n];
        for (int i = 0; i < n; i++) {
            double z = 2 * random.nextDouble() - 1;
            double ra = 2 * Math.PI * random.nextDouble();
            double r = Math.sqrt(1 - z * z);
            directions[3 * i] = (float) (r * Math.cos(ra));
            directions[3 * i + 1] = (float) (r * Math.sin(ra));
            directions[3 * i + 2] = (float) z;
            irradiance[i] = (float) Math.pow(10, -0.4 * (magnitude(i) - MoonPosition.SUN_MAGNITUDE));
        }
        return new StarCatalogue(directions, irradiance);
    }

    /** The magnitude of the i-th brightest star (from 0) by the count law. */
    static double magnitude(int i) {
        return (Math.log10(i + 0.5) - COUNT_AT_ZERO) / COUNT_SLOPE;
    }

    /** How many stars. */
    public int count() {
        return irradiance.length;
    }
}

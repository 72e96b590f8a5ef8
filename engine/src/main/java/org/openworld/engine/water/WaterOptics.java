package org.openworld.engine.water;

import org.joml.Vector3f;

/**
 * What the water does to light passing through it, per colour channel (red 650 nm, green 550 nm, blue 450 nm):
 * how much it takes away per metre, and how much deep water sends back, seen from above and from inside. GL-free.
 *
 * <p><b>Model.</b> Pure water absorbs {@code a_w} (Pope and Fry 1997: 0.35, 0.057, 0.0145 per metre), which is
 * why water is blue; what is dissolved and suspended in it, summed up by the clarity {@code C} (metres), absorbs
 * {@code 0.1/C} more and scatters {@code b = 0.9/C}. Then
 * <pre>
 *   extinction  σ  = a_w + 0.1/C + 0.9/C          (Beer–Lambert: T = exp(−σ d) over a path d)
 *   backscatter bb = bb_w + 0.019 b               (bb_w: pure water's, 0.0008, 0.0017, 0.0036 per metre, ~λ⁻⁴)
 *   body        R∞ = 0.33 bb / (a + bb)           (Gordon's deep-water reflectance, a = a_w + 0.1/C)
 *   inside      L  = ω / 2,  ω = b / σ            (the light scattered towards a swimmer's eye, per unit of
 *                                                  light entering the water: single scattering of the downwelling
 *                                                  light, half of it sent into the lower hemisphere)
 * </pre>
 * A path of d metres leaves {@code exp(−σ d)} of what lies behind it and adds {@code (1 − exp(−σ d))} of the body
 * colour: {@code body} looking down into the water from above, {@code inside} looking through it from within. Limits: three wavelengths, not a spectrum; single numbers for everything a real lake varies (algae,
 * silt, depth); the light under the water is attenuated along one vertical path only, without caustics.
 */
record WaterOptics(Vector3f extinction, Vector3f body, Vector3f inside) {

    private static final float[] PURE_ABSORPTION = {0.35f, 0.057f, 0.0145f};
    private static final float[] PURE_BACKSCATTER = {0.0008f, 0.0017f, 0.0036f};
    /** Shares of 1/clarity that the dissolved and suspended matter absorbs and scatters. */
    private static final float MATTER_ABSORPTION = 0.1f;
    private static final float MATTER_SCATTERING = 0.9f;
    /** Fraction of the particles' scattering that goes backwards (Petzold's ocean measurements, about 2%). */
    private static final float PARTICLE_BACKSCATTER = 0.019f;
    /** Gordon's factor from backscatter ratio to reflectance just below the surface. */
    private static final float GORDON = 0.33f;

    /** @param clarity metres, positive: {@code water.clarity} */
    static WaterOptics of(double clarity) {
        if (!(clarity > 0)) {
            throw new IllegalArgumentException("water clarity must be positive, got " + clarity);
        }
        float[] sigma = new float[3];
        float[] body = new float[3];
        float[] inside = new float[3];
        float matter = (float) (1 / clarity);
        for (int c = 0; c < 3; c++) {
            float absorption = PURE_ABSORPTION[c] + MATTER_ABSORPTION * matter;
            float scattering = MATTER_SCATTERING * matter;
            float backscatter = PURE_BACKSCATTER[c] + PARTICLE_BACKSCATTER * scattering;
            sigma[c] = absorption + scattering;
            body[c] = GORDON * backscatter / (absorption + backscatter);
            inside[c] = 0.5f * (scattering + PURE_BACKSCATTER[c]) / sigma[c];
        }
        return new WaterOptics(new Vector3f(sigma), new Vector3f(body), new Vector3f(inside));
    }
}

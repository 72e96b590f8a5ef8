package org.openworld.engine.water;

/**
 * How much light a smooth water surface reflects, from the Fresnel equations for unpolarised light. GL-free: the
 * water system tabulates it ({@link #table}) and the shader reads the table, so what is tested here is what is drawn.
 *
 * <p>For light meeting the surface at {@code cos θᵢ} from a medium of index {@code n₁} into one of {@code n₂}:
 * {@code sin θₜ = n₁/n₂ sin θᵢ} (Snell); if {@code sin θₜ ≥ 1} every bit is reflected (total internal reflection,
 * seen from under the water beyond the critical angle, 48.6°); otherwise
 * <pre>
 *   rₛ = (n₁ cos θᵢ − n₂ cos θₜ) / (n₁ cos θᵢ + n₂ cos θₜ)
 *   rₚ = (n₁ cos θₜ − n₂ cos θᵢ) / (n₁ cos θₜ + n₂ cos θᵢ)
 *   R  = (rₛ² + rₚ²) / 2
 * </pre>
 * From the air, water reflects 2% straight down and all at grazing angles: the reason a lake is a window at your
 * feet and a mirror near the horizon. Schlick's approximation {@code R₀ + (1 − R₀)(1 − cos θ)⁵} is within 0.01 of
 * this from the air but misses total internal reflection, which the table gives for free.
 */
final class Fresnel {

    /** Refractive index of water for visible light (fresh water, 20 °C, 589 nm). */
    static final double WATER_INDEX = 1.333;
    /** Refractive index of air. */
    static final double AIR_INDEX = 1.000293;

    private Fresnel() {
    }

    /**
     * The reflected fraction of unpolarised light.
     *
     * @param cosIncident cosine of the angle between the ray and the normal, 0..1
     * @param n1          refractive index on the incident side
     * @param n2          refractive index on the far side
     */
    static double reflectance(double cosIncident, double n1, double n2) {
        double cosI = Math.min(1, Math.max(0, cosIncident));
        double sinT = n1 / n2 * Math.sqrt(1 - cosI * cosI);
        if (sinT >= 1) {
            return 1;
        }
        double cosT = Math.sqrt(1 - sinT * sinT);
        double rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
        double rp = (n1 * cosT - n2 * cosI) / (n1 * cosT + n2 * cosI);
        return (rs * rs + rp * rp) / 2;
    }

    /**
     * The reflectance at {@code size} cosines from 0 to 1 (texel centres: {@code cos = (i + 0.5) / size}), row 0 from
     * the air into the water, row 1 from the water into the air: a {@code size × 2} table.
     */
    static float[] table(int size) {
        float[] table = new float[2 * size];
        for (int i = 0; i < size; i++) {
            double cos = (i + 0.5) / size;
            table[i] = (float) reflectance(cos, AIR_INDEX, WATER_INDEX);
            table[size + i] = (float) reflectance(cos, WATER_INDEX, AIR_INDEX);
        }
        return table;
    }
}

package org.openworld.engine.environment;

import org.joml.Vector3d;
import org.joml.Vector3dc;
import org.joml.Vector3f;
import org.joml.Vector3fc;

/**
 * The light of the sky and the ground around on a surface of any normal, as order-2 spherical harmonics (Ramamoorthi
 * and Hanrahan 2001, "An efficient representation for irradiance environment maps"): the radiance around the scene
 * is projected onto the nine real harmonics Y_lm (l ≤ 2), and the irradiance E(n) = ∫ L(ω) max(n·ω, 0) dω is then
 * Σ Â_l L_lm Y_lm(n) with the clamped cosine's coefficients Â_0 = π, Â_1 = 2π/3, Â_2 = π/4. Irradiance is so smooth
 * that these nine terms hold it within a few per cent for any sky; a uniform hemisphere of radiance, whose
 * irradiance is linear in n, they hold exactly.
 *
 * <p>Harmonics in the world's axes (y up): Y_00 = 0.282095; Y_1m = 0.488603 (y, z, x); Y_2m = 1.092548 xy,
 * 1.092548 yz, 0.315392 (3y² − 1), 1.092548 xz, 0.546274 (x² − z²). Radiance and irradiance are linear RGB in the
 * sun's display units. Built by accumulating {@link #add samples} of the radiance (a quadrature over the sphere) and
 * {@link #addLowerHemisphere uniform ground light}, with {@link #hiddenBy the light of the terrain} that stands in
 * for the sky where the relief hides it; immutable once handed to a {@link Sun}.
 */
public final class SkyIrradiance {

    /** Number of coefficients, each an RGB triple. */
    public static final int COUNT = 9;
    private static final double[] NORM = {0.282095, 0.488603, 0.488603, 0.488603, 1.092548, 1.092548, 0.315392,
        1.092548, 0.546274};
    /** Â_l of the clamped cosine per coefficient: π for l = 0, 2π/3 for l = 1, π/4 for l = 2. */
    private static final double[] COSINE = {Math.PI, 2 * Math.PI / 3, 2 * Math.PI / 3, 2 * Math.PI / 3,
        Math.PI / 4, Math.PI / 4, Math.PI / 4, Math.PI / 4, Math.PI / 4};

    /** L_lm, RGB: radiance coefficients. */
    private final double[] radiance = new double[3 * COUNT];
    /** π × the radiance of the terrain that hides part of the sky, RGB; black until {@link #hiddenBy} sets it. */
    private final Vector3d hidden = new Vector3d();

    /** The polynomial part of each harmonic at the unit direction (x, y, z): Y_lm = NORM · poly. */
    static double[] polynomials(double x, double y, double z, double[] out) {
        out[0] = 1;
        out[1] = y;
        out[2] = z;
        out[3] = x;
        out[4] = x * y;
        out[5] = y * z;
        out[6] = 3 * y * y - 1;
        out[7] = x * z;
        out[8] = x * x - z * z;
        return out;
    }

    /** The nine harmonics Y_lm at the unit direction d. */
    public static double[] harmonics(Vector3dc d) {
        double[] y = polynomials(d.x(), d.y(), d.z(), new double[COUNT]);
        for (int i = 0; i < COUNT; i++) {
            y[i] *= NORM[i];
        }
        return y;
    }

    /** Adds radiance L from the unit direction d over the solid angle dOmega (one term of ∫ L Y_lm dω). */
    public SkyIrradiance add(Vector3dc d, Vector3dc l, double dOmega) {
        double[] y = harmonics(d);
        for (int i = 0; i < COUNT; i++) {
            radiance[3 * i] += l.x() * y[i] * dOmega;
            radiance[3 * i + 1] += l.y() * y[i] * dOmega;
            radiance[3 * i + 2] += l.z() * y[i] * dOmega;
        }
        return this;
    }

    /**
     * Adds a uniform radiance L from every direction below the horizon, in closed form: ∫_{y<0} Y_00 dω = 2π·0.282095,
     * ∫_{y<0} Y_10 dω = −π·0.488603, and every other harmonic integrates to 0 over a half sphere about y. Its
     * irradiance is then exactly πL(1 − n_y)/2: nothing on a surface facing up, πL on one facing down.
     */
    public SkyIrradiance addLowerHemisphere(Vector3dc l) {
        return addHemisphere(l, -1);
    }

    /** The same with uniform radiance above the horizon (πL(1 + n_y)/2): Y_10 integrates to +π·0.488603 there. */
    public SkyIrradiance addUpperHemisphere(Vector3dc l) {
        return addHemisphere(l, 1);
    }

    /** Uniform radiance l over the half sphere on the side {@code side} (+1 up, −1 down) of the horizon. */
    private SkyIrradiance addHemisphere(Vector3dc l, int side) {
        double[] weights = {2 * Math.PI * NORM[0], side * Math.PI * NORM[1]};
        for (int i = 0; i < weights.length; i++) {
            radiance[3 * i] += l.x() * weights[i];
            radiance[3 * i + 1] += l.y() * weights[i];
            radiance[3 * i + 2] += l.z() * weights[i];
        }
        return this;
    }

    /**
     * Sets what the terrain hiding part of the sky gives in its place, as the irradiance a surface would get if that
     * terrain filled its whole hemisphere (π × its radiance); a share 1 − V of the sky hidden then gives
     * {@code V · E(n) + (1 − V) · e} ({@code frame.glsl}'s two-argument skyIrradiance).
     */
    public SkyIrradiance hiddenBy(Vector3dc e) {
        hidden.set(e);
        return this;
    }

    /** Radiance coefficient L_lm (index 0..8 in the order of the class comment), RGB. */
    public Vector3d coefficient(int i, Vector3d out) {
        return out.set(radiance[3 * i], radiance[3 * i + 1], radiance[3 * i + 2]);
    }

    /** E(n) = Σ Â_l L_lm Y_lm(n) at the unit normal n, RGB. */
    public Vector3d irradiance(Vector3dc n, Vector3d out) {
        double[] poly = polynomials(n.x(), n.y(), n.z(), new double[COUNT]);
        out.zero();
        for (int i = 0; i < COUNT; i++) {
            double w = COSINE[i] * NORM[i] * poly[i];
            out.add(radiance[3 * i] * w, radiance[3 * i + 1] * w, radiance[3 * i + 2] * w);
        }
        return out;
    }

    /**
     * The nine RGB factors a shader multiplies the polynomials by (Â_l · L_lm · NORM_lm), so that E(n) =
     * c0 + c1·y + c2·z + c3·x + c4·xy + c5·yz + c6·(3y² − 1) + c7·xz + c8·(x² − z²): 9 multiply-adds per pixel, no
     * texture read ({@code shaders/common/frame.glsl}, skyIrradiance); then, tenth, the {@link #hiddenBy hidden
     * sky's light}.
     */
    public Vector3fc[] shaderFactors() {
        Vector3fc[] factors = new Vector3fc[COUNT + 1];
        for (int i = 0; i < COUNT; i++) {
            double w = COSINE[i] * NORM[i];
            factors[i] = new Vector3f((float) (radiance[3 * i] * w), (float) (radiance[3 * i + 1] * w),
                    (float) (radiance[3 * i + 2] * w));
        }
        factors[COUNT] = new Vector3f(hidden);
        return factors;
    }

    /** A sky of uniform radiance whose irradiance on an upward surface is {@code up}, and a black ground. */
    public static SkyIrradiance uniformSky(Vector3fc up) {
        return new SkyIrradiance().addUpperHemisphere(new Vector3d(up).div(Math.PI));
    }
}

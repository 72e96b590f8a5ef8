package org.openworld.engine.particles;

import java.util.SplittableRandom;
import org.joml.Vector3fc;

/**
 * The snow's update rule, on the CPU: the reference that {@code shaders/particles/update.vert} is tested against,
 * in the same float operations, and the place its analysis is checked (paper section 4).
 *
 * <p>Each step of dt seconds, for a flake at p moving at v, with g the downward pull, k the drag, w the wind and σ
 * the strength of the Brownian term (semi-implicit Euler: the new velocity moves the flake):
 * <pre>
 *   v ← v + dt · (−g ŷ + k (w − v)) + σ √dt ξ      ξ: three independent N(0, 1), new every step
 *   p ← p + dt · v
 * </pre>
 * then p is wrapped into the cube of side L around the eye c (p ← c + ((p − c + L/2) mod L) − L/2, each axis; GLSL's
 * {@code mod}, a − L · floor(a / L)). A flake that comes back in through a side face keeps its height above the
 * ground: walking downhill, the air ahead fills with the snow that leaves behind, not only above the ground left
 * behind. A flake below the ground is put back at the cube's top, as far below it as it was below the ground.
 *
 * <p>The analysis: in still air the velocity relaxes to the terminal velocity −(g / k) ŷ, as
 * v(t) = −(g/k)(1 − e^(−kt)) from rest; the step's fixed point is exactly −(g / k) ŷ. With the random term, each
 * component is an Ornstein–Uhlenbeck process whose spread settles at σ² dt / (1 − (1 − k dt)²), which tends to
 * σ² / (2k) for small steps.
 *
 * <p>ξ comes from a hash of the particle's index and a key for the step ({@link #stepKey}): seeded, so a run
 * repeats exactly, and the same on the GPU and here.
 */
public final class SnowMotion {

    /** Floats per flake in the state: position xyz (m), then velocity xyz (m/s). The GPU buffers' layout too. */
    public static final int FLOATS = 6;
    /**
     * Tries to place a flake in the air, by rejection, before it is left where it is: all 64 fail with a chance of
     * 5e-20 where half the cube is ground, and of 1e-3 (a flake left underground, which its first step puts at the
     * top) where 90% is.
     */
    private static final int PLACEMENT_TRIES = 64;
    private static final float TWO_PI = (float) (2 * Math.PI);

    /**
     * The forces of one step.
     *
     * @param gravity  g, m/s²
     * @param drag     k, 1/s
     * @param kick     σ √dt, m/s: the Brownian term's size per step (0: off)
     * @param wind     w, m/s
     * @param step     dt, s
     */
    public record Forces(float gravity, float drag, float kick, Vector3fc wind, float step) {
    }

    /**
     * The cube of snow: its centre (the eye) and side, metres.
     */
    public record Volume(Vector3fc centre, float side) {
    }

    private SnowMotion() {
    }

    /** Advances every flake of {@code state} by one step, in place. */
    public static void step(float[] state, Forces f, Volume volume, GroundPatch ground, int stepKey) {
        float[] xi = new float[3];
        float side = volume.side();
        float half = 0.5f * side;
        Vector3fc c = volume.centre();
        for (int i = 0; i < state.length / FLOATS; i++) {
            int o = i * FLOATS;
            if (f.kick() > 0) { // as the shader: no random numbers drawn when the term is off
                gaussians(i ^ stepKey, xi);
            }
            // gravity, drag towards the wind, the Brownian kick
            float vx = state[o + 3] + f.step() * (f.drag() * (f.wind().x() - state[o + 3])) + f.kick() * xi[0];
            float vy = state[o + 4] + f.step() * (-f.gravity() + f.drag() * (f.wind().y() - state[o + 4]))
                    + f.kick() * xi[1];
            float vz = state[o + 5] + f.step() * (f.drag() * (f.wind().z() - state[o + 5])) + f.kick() * xi[2];
            // the move, then back into the cube through the opposite side face, as high above the ground
            float mx = state[o] + f.step() * vx;
            float my = state[o + 1] + f.step() * vy;
            float mz = state[o + 2] + f.step() * vz;
            float ax = mx - c.x() + half;
            float az = mz - c.z() + half;
            float lapsX = (float) Math.floor(ax / side);
            float lapsZ = (float) Math.floor(az / side);
            float px = c.x() + (ax - side * lapsX) - half;
            float pz = c.z() + (az - side * lapsZ) - half;
            float py = my;
            if (lapsX != 0 || lapsZ != 0) {
                py += ground.heightAt(px, pz) - ground.heightAt(mx, mz);
            }
            // through the top or bottom face; a flake below the ground goes back to the top
            float ay = py - c.y() + half;
            py = c.y() + (ay - side * (float) Math.floor(ay / side)) - half;
            float groundY = ground.heightAt(px, pz);
            if (py < groundY) {
                py = c.y() + half - (groundY - py);
            }
            state[o] = px;
            state[o + 1] = py;
            state[o + 2] = pz;
            state[o + 3] = vx;
            state[o + 4] = vy;
            state[o + 5] = vz;
        }
    }

    /**
     * A fresh snowfall: {@code count} flakes spread evenly through the air of the cube (above the ground), all
     * moving at {@code velocity}, the steady one, so the first frames look like the thousandth.
     */
    public static float[] seed(int count, Volume volume, GroundPatch ground, Vector3fc velocity, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        float[] state = new float[count * FLOATS];
        float half = 0.5f * volume.side();
        for (int i = 0; i < count; i++) {
            float x = 0;
            float y = 0;
            float z = 0;
            for (int attempt = 0; attempt < PLACEMENT_TRIES; attempt++) {
                x = volume.centre().x() + (float) random.nextDouble(-half, half);
                y = volume.centre().y() + (float) random.nextDouble(-half, half);
                z = volume.centre().z() + (float) random.nextDouble(-half, half);
                if (y >= ground.heightAt(x, z)) {
                    break;
                }
            }
            int o = i * FLOATS;
            state[o] = x;
            state[o + 1] = y;
            state[o + 2] = z;
            state[o + 3] = velocity.x();
            state[o + 4] = velocity.y();
            state[o + 5] = velocity.z();
        }
        return state;
    }

    /** The key of step {@code step} of a run seeded with {@code seed}: mixed into each flake's index for its ξ. */
    public static int stepKey(int seed, long step) {
        return hash((int) step ^ hash(seed));
    }

    /** Terminal velocity of the rule in still air, m/s downwards: g / k. */
    public static double terminalVelocity(double gravity, double drag) {
        return gravity / drag;
    }

    /** Variance each velocity component settles at under the Brownian term, (m/s)²: σ² dt / (1 − (1 − k dt)²). */
    public static double settledVariance(double brownian, double drag, double step) {
        double keep = 1 - drag * step;
        return brownian * brownian * step / (1 - keep * keep);
    }

    /**
     * Three independent standard normal numbers from one hash input: four uniforms in (0, 1] by chained hashes,
     * then Box–Muller twice (the fourth normal is thrown away).
     */
    static void gaussians(int input, float[] dest) {
        int h1 = hash(input);
        int h2 = hash(h1);
        int h3 = hash(h2);
        int h4 = hash(h3);
        float r1 = (float) Math.sqrt(-2f * (float) Math.log(uniform(h1)));
        float r2 = (float) Math.sqrt(-2f * (float) Math.log(uniform(h3)));
        float a1 = TWO_PI * uniform(h2);
        float a2 = TWO_PI * uniform(h4);
        dest[0] = r1 * (float) Math.cos(a1);
        dest[1] = r1 * (float) Math.sin(a1);
        dest[2] = r2 * (float) Math.cos(a2);
    }

    /** The top 24 bits of a hash as a float in (0, 1], exactly: never 0, so its logarithm is finite. */
    static float uniform(int hash) {
        return ((hash >>> 8) + 1) * 0x1p-24f;
    }

    /**
     * The PCG hash (Jarzynski and Olano, "Hash Functions for GPU Rendering", JCGT 2020): one round of a
     * permuted congruential generator, on 32-bit unsigned integers (Java's int arithmetic wraps the same way; its
     * {@code >>>} is GLSL's {@code >>} on uint).
     */
    static int hash(int v) {
        int state = v * 747796405 + (int) 2891336453L;
        int word = ((state >>> ((state >>> 28) + 4)) ^ state) * 277803737;
        return (word >>> 22) ^ word;
    }
}

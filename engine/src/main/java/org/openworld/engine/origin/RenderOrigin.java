package org.openworld.engine.origin;

import org.joml.Vector3f;

/**
 * The point the GPU measures positions from: the viewer's eye rounded to a multiple of {@link #step()} on x and z
 * (y stays 0, so heights and the air's altitude are the world's own). The CPU holds it, and every world position
 * it hands the GPU, in double; the GPU sees only {@code p − origin}, a few kilometres at most, where a float keeps
 * its millimetres. Whatever a shader reads by world position (a texture, a noise lattice, a clipmap's window) gets
 * the origin's share reduced modulo its own period here, in double ({@link #reduce}), so the shader adds a small
 * number to a small number.
 *
 * <p>The step is the terrain's tile (the side of a root of the unbounded world): a whole number of the tile's and of
 * every streamed level's samples, so the origin's offset on a height map is an integer number of samples and a
 * tile-periodic lookup needs no offset at all. The origin moves in whole steps, rarely; nothing on the screen moves
 * when it does, since every offset moves with it. A world resource: the engine moves it to the viewer before each
 * frame's passes ({@link #follow}), the systems read it when they draw.
 */
public final class RenderOrigin {

    /** The step when no terrain sets one, metres: a power of two, as the tiles are. */
    public static final double DEFAULT_STEP = 4096;

    private final double step;
    private double x;
    private double z;

    /** An origin at (0, 0) that moves in steps of {@code step} metres. */
    public RenderOrigin(double step) {
        if (!(step > 0) || !Double.isFinite(step)) {
            throw new IllegalArgumentException("the render origin's step must be a positive number of metres, got "
                    + step);
        }
        this.step = step;
    }

    /** Moves the origin to the multiple of the step nearest the eye (x, z, metres); true when it moved. */
    public boolean follow(double eyeX, double eyeZ) {
        double nx = step * Math.rint(eyeX / step) + 0.0; // + 0.0 turns −0 into 0
        double nz = step * Math.rint(eyeZ / step) + 0.0;
        boolean moved = nx != x || nz != z;
        x = nx;
        z = nz;
        return moved;
    }

    /** Metres between the origin's possible places on either axis. */
    public double step() {
        return step;
    }

    /** The origin's x, metres (a multiple of the step). */
    public double x() {
        return x;
    }

    /** The origin's z, metres (a multiple of the step). */
    public double z() {
        return z;
    }

    /** A world x (metres, double) as the GPU takes it: from the origin, rounded to float once. */
    public float relativeX(double worldX) {
        return (float) (worldX - x);
    }

    /** A world z (metres, double) as the GPU takes it. */
    public float relativeZ(double worldZ) {
        return (float) (worldZ - z);
    }

    /** A world point (metres, double) as the GPU takes it. */
    public Vector3f relative(double worldX, double worldY, double worldZ) {
        return new Vector3f(relativeX(worldX), (float) worldY, relativeZ(worldZ));
    }

    /** World (x, z) pairs, metres, as the GPU takes them: each from the origin, rounded to float once. */
    public float[] relativePairs(float[] xz) {
        float[] out = new float[xz.length];
        for (int i = 0; i + 1 < xz.length; i += 2) {
            out[i] = relativeX(xz[i]);
            out[i + 1] = relativeZ(xz[i + 1]);
        }
        return out;
    }

    /**
     * {@code value} modulo {@code period}, in [0, period): what a function of period {@code period} needs of a large
     * coordinate. Java's {@code %} on doubles is IEEE's fmod, which is exact (the remainder of two doubles is a
     * double), so the only error is the one {@code value} already carries.
     */
    public static double reduce(double value, double period) {
        if (!(period > 0) || !Double.isFinite(period)) {
            throw new IllegalArgumentException("a period must be a positive number, got " + period);
        }
        double r = value % period;
        if (r < 0) {
            r += period; // may round up to period itself when r is tinier than period's last bit
        }
        return r >= period ? 0 : r;
    }
}

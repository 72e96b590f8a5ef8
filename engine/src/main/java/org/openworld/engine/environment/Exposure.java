package org.openworld.engine.environment;

/**
 * How bright the scene is shown: the factor from display units (1 = a white surface facing the sun above the
 * atmosphere) to the tone mapper's input, in {@code shaders/common/color.glsl}, and how far the picture has shifted
 * to the rods' blue and grey vision of the night. Written by the system that models the sky, from the light of the
 * moment (as an eye or a camera adapts); 1 and no shift when there is none.
 *
 * @param scale    linear multiplier, &gt; 0
 * @param scotopic the rods' share of vision, 0 (day, colour as it is) to 1 (night: the Purkinje shift in full)
 */
public record Exposure(float scale, float scotopic) {

    /** Shown as it is: for worlds lit by the engine's fixed noon sun. */
    public static final Exposure NONE = new Exposure(1);

    /** An exposure by day, with no shift. */
    public Exposure(float scale) {
        this(scale, 0);
    }

    public Exposure {
        if (!(scale > 0 && Float.isFinite(scale))) {
            throw new IllegalArgumentException("exposure must be a positive number, got " + scale);
        }
        if (!(scotopic >= 0 && scotopic <= 1)) {
            throw new IllegalArgumentException("the rods' share must be in [0, 1], got " + scotopic);
        }
    }
}

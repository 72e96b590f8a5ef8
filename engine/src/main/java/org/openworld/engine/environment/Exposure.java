package org.openworld.engine.environment;

/**
 * How bright the scene is shown: the factor from display units (1 = a white surface facing the sun above the
 * atmosphere) to the tone mapper's input, in {@code shaders/common/color.glsl}. Written by the system that models
 * the sky, from the light of the moment (as an eye or a camera adapts); 1 when there is none.
 *
 * @param scale linear multiplier, &gt; 0
 */
public record Exposure(float scale) {

    /** Shown as it is: for worlds lit by the engine's fixed noon sun. */
    public static final Exposure NONE = new Exposure(1);

    public Exposure {
        if (!(scale > 0 && Float.isFinite(scale))) {
            throw new IllegalArgumentException("exposure must be a positive number, got " + scale);
        }
    }
}

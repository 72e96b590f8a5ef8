package org.openworld.engine.core;

/**
 * The render passes of a frame, in the order the engine runs them (docs/design.md, "Passes"). Each pass carries its own
 * camera: the sun's for {@link #SHADOW}, the mirrored one for {@link #REFLECTION}, the viewer's for the others.
 */
public enum Pass {
    /** Depth from the sun into the shadow map. The drawing system binds its own depth target. */
    SHADOW,
    /** The scene seen by the camera mirrored in the water plane, into the water's texture. */
    REFLECTION,
    /** The picture: opaque terrain, sky, water, then transparent particles, into the engine's scene target. */
    MAIN,
    /** Screen-space things drawn over the picture: HUD and UI. */
    OVERLAY;

    /** The label used in timings and in {@code frames.csv}, e.g. {@code main}. */
    public String label() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }
}

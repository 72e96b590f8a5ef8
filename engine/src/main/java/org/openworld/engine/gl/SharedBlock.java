package org.openworld.engine.gl;

/**
 * Uniform blocks every shader may declare without its system binding them: each has a fixed binding point, and every
 * program that declares the block gets it bound there at link time. The engine keeps a buffer bound at each point
 * before every pass.
 */
public enum SharedBlock {
    /** {@code FrameBlock}: the pass's camera, the sun, time ({@code shaders/common/frame.glsl}, {@link FrameUniforms}). */
    FRAME("FrameBlock", 0),
    /** {@code ShadowBlock}: the sun's shadow cascades ({@code shaders/common/shadow.glsl}). */
    SHADOW("ShadowBlock", 1),
    /** {@code CloudShadowBlock}: where the cloud shadow map lies ({@code shaders/common/shadow.glsl}). */
    CLOUD_SHADOW("CloudShadowBlock", 2);

    private final String block;
    private final int binding;

    SharedBlock(String block, int binding) {
        this.block = block;
        this.binding = binding;
    }

    /** The block's name in GLSL. */
    public String block() {
        return block;
    }

    /** The uniform buffer binding point. */
    public int binding() {
        return binding;
    }
}

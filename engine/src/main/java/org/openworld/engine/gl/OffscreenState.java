package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL30C.GL_BLEND;
import static org.lwjgl.opengl.GL30C.GL_CLIP_DISTANCE0;
import static org.lwjgl.opengl.GL30C.GL_CULL_FACE;
import static org.lwjgl.opengl.GL30C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL30C.GL_DRAW_FRAMEBUFFER_BINDING;
import static org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.GL_SCISSOR_TEST;
import static org.lwjgl.opengl.GL30C.GL_VIEWPORT;
import static org.lwjgl.opengl.GL30C.glBindFramebuffer;
import static org.lwjgl.opengl.GL30C.glDisable;
import static org.lwjgl.opengl.GL30C.glEnable;
import static org.lwjgl.opengl.GL30C.glGetInteger;
import static org.lwjgl.opengl.GL30C.glGetIntegerv;
import static org.lwjgl.opengl.GL30C.glIsEnabled;
import static org.lwjgl.opengl.GL30C.glViewport;

/**
 * What a pass into a texture, run in the middle of a frame (a bake, a streamed block's pass), changes and must give
 * back: the draw framebuffer, the viewport, and the depth test, blending, face culling, scissor test and first clip
 * distance, which it turns off for a full-screen triangle (inside a pass that scissors its target or clips at a
 * plane, as the water's reflection does, they would cut the triangle short). Opened at the pass's start, closed at
 * its end:
 * <pre>
 *   try (OffscreenState state = OffscreenState.enter()) { ...bind a target, set a viewport, draw... }
 * </pre>
 */
public final class OffscreenState implements AutoCloseable {

    private static final int[] CAPS = {GL_DEPTH_TEST, GL_BLEND, GL_CULL_FACE, GL_SCISSOR_TEST, GL_CLIP_DISTANCE0};

    private final int framebuffer;
    private final int[] viewport = new int[4];
    private final boolean[] enabled = new boolean[CAPS.length];

    private OffscreenState() {
        framebuffer = glGetInteger(GL_DRAW_FRAMEBUFFER_BINDING);
        glGetIntegerv(GL_VIEWPORT, viewport);
        for (int i = 0; i < CAPS.length; i++) {
            enabled[i] = glIsEnabled(CAPS[i]);
            glDisable(CAPS[i]);
        }
    }

    /**
     * Notes the framebuffer, viewport and tests in use, and turns the depth test, blending, culling, scissor and clip
     * distance off.
     */
    public static OffscreenState enter() {
        return new OffscreenState();
    }

    /** Gives the framebuffer, the viewport and the tests back as they were. */
    @Override
    public void close() {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
        for (int i = 0; i < CAPS.length; i++) {
            if (enabled[i]) {
                glEnable(CAPS[i]);
            }
        }
    }
}

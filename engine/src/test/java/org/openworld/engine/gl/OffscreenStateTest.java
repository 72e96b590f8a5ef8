package org.openworld.engine.gl;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL30C.*;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;

/**
 * A pass into a texture run in the middle of another pass ({@link OffscreenState}): inside a pass that scissors its
 * target to a corner and clips at a plane, as the water's reflection does, a full-screen triangle still covers the
 * whole texture, and the outer pass gets its framebuffer, viewport and tests back.
 */
@GlTest
class OffscreenStateTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    @Test
    void aPassInsideAScissoredClippedPassCoversItsTargetAndGivesTheStateBack() {
        ShaderLibrary library = new ShaderLibrary(GL.context(), ShaderSources.classpath());
        try (ShaderProgram program = library.program("test/fullscreen.vert", "test/solid.frag");
             Framebuffer outer = new Framebuffer(GL.context(), 64, 64, Format.RGBA8, null, Sampling.NEAREST_CLAMP);
             Framebuffer inner = new Framebuffer(GL.context(), 32, 32, Format.RGBA8, null, Sampling.NEAREST_CLAMP);
             Mesh triangle = GlTestSupport.fullScreenTriangle(GL.context())) {
            inner.bind();
            glClearColor(0, 0, 0, 0);
            glClear(GL_COLOR_BUFFER_BIT);
            // the outer pass: its own target and viewport, a scissored corner, a clip plane, the depth test
            outer.bind();
            glViewport(8, 8, 48, 48);
            glScissor(0, 0, 4, 4);
            glEnable(GL_SCISSOR_TEST);
            glEnable(GL_CLIP_DISTANCE0);
            glEnable(GL_DEPTH_TEST);
            try (OffscreenState state = OffscreenState.enter()) {
                inner.bind();
                glViewport(0, 0, 32, 32);
                program.use();
                program.vec4("uColor").set(1, 0, 0, 1);
                triangle.draw(new DrawStats());
            }
            int[] viewport = new int[4];
            glGetIntegerv(GL_VIEWPORT, viewport);
            assertArrayEquals(new int[] {8, 8, 48, 48}, viewport, "the outer viewport");
            assertEquals(outer.id(), glGetInteger(GL_DRAW_FRAMEBUFFER_BINDING), "the outer framebuffer");
            assertTrue(glIsEnabled(GL_SCISSOR_TEST), "the scissor test back");
            assertTrue(glIsEnabled(GL_CLIP_DISTANCE0), "the clip plane back");
            assertTrue(glIsEnabled(GL_DEPTH_TEST), "the depth test back");
            glDisable(GL_SCISSOR_TEST);
            glDisable(GL_CLIP_DISTANCE0);
            glDisable(GL_DEPTH_TEST);

            Image image = inner.read();
            int unwritten = 0;
            for (int y = 0; y < 32; y++) {
                for (int x = 0; x < 32; x++) {
                    unwritten += image.channel(x, y, 0) == 255 ? 0 : 1;
                }
            }
            assertEquals(0, unwritten, "texels of the inner target the triangle left unwritten");
        }
    }
}

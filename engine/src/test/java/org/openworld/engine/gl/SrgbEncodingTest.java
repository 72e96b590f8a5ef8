package org.openworld.engine.gl;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL11C.*;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;

/**
 * The shaders' sRGB encoding ({@code common/color.glsl}'s {@code linearToSrgb}, a fit by three square roots instead
 * of a power) against the exact sRGB curve, on the real driver: every 8-bit value it writes is the exact curve's
 * value rounded, give or take the fit's quarter of a level.
 */
@GlTest
class SrgbEncodingTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    private static final int WIDTH = 1024;
    /** Half a level of the target's rounding plus the fit's largest error, a quarter of a level. */
    private static final double TOLERANCE_LEVELS = 0.75;

    /** IEC 61966-2-1's encoding of a linear value in 0..1. */
    static double exactSrgb(double linear) {
        return linear <= 0.0031308 ? 12.92 * linear : 1.055 * Math.pow(linear, 1 / 2.4) - 0.055;
    }

    @Test
    void everyLevelIsTheExactCurvesRounded() {
        ShaderLibrary library = new ShaderLibrary(GL.context(), ShaderSources.classpath());
        try (ShaderProgram program = library.program("test/fullscreen.vert", "test/colour/srgb-ramp.frag");
             Framebuffer target = new Framebuffer(GL.context(), WIDTH, 1, Format.RGBA8, null, Sampling.NEAREST_CLAMP);
             Mesh triangle = GlTestSupport.fullScreenTriangle(GL.context())) {
            target.bind();
            glClearColor(0, 0, 0, 0);
            glClear(GL_COLOR_BUFFER_BIT);
            program.use();
            program.float1("width").set(WIDTH);
            triangle.draw(new DrawStats());
            Image image = target.read();
            double worst = 0;
            int worstColumn = -1;
            for (int x = 0; x < WIDTH; x++) {
                double t = x / (WIDTH - 1.0);
                double error = Math.abs(image.channel(x, 0, 0) - 255 * exactSrgb(t * t));
                if (error > worst) {
                    worst = error;
                    worstColumn = x;
                }
            }
            assertTrue(worst <= TOLERANCE_LEVELS, "the encoding is off the sRGB curve by " + worst
                    + " levels at linear " + Math.pow(worstColumn / (WIDTH - 1.0), 2));
        }
    }
}

package org.openworld.engine.temporal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.glClear;
import static org.lwjgl.opengl.GL11C.glClearColor;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.GlTest;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.Image;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.ShaderLibrary;
import org.openworld.engine.gl.ShaderSources;

/**
 * The TAA pass ({@code shaders/temporal/taa.frag}) on real GL, fed frames that alternate between two flat greys, as
 * a pixel alternates when its jittered samples fall on a sub-pixel feature and beside it. Each frame's 3 × 3
 * neighbourhood is one grey, so a clamp to it keeps nothing of the history: under a still view the pass must not
 * clamp, and settles to the mean of the frames; under a view that turns a pixel a frame it must clamp, and shows the
 * last frame.
 */
@GlTest
class TemporalAntialiasTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    private static final int SIZE = 8;
    /** One jitter cycle of frames, blended as their exact mean (a blend of 1 / FRAMES). */
    private static final int FRAMES = 32;
    /** The two greys, 8-bit sRGB-encoded levels: the even frames' and the odd frames'. */
    private static final int EVEN = 51;
    private static final int ODD = 153;
    /**
     * Levels: the scene target's and the output's rounding (half a level each); the RGBA16F history's error at
     * these values is a twentieth of a level.
     */
    private static final double TOLERANCE = 1;

    /** The centre pixel's red level after FRAMES frames, the view turned by {@code yawPerFrame} degrees a frame. */
    private static int settled(double yawPerFrame) {
        try (TemporalAntialias taa = new TemporalAntialias(GL.context(),
                new ShaderLibrary(GL.context(), ShaderSources.classpath()));
             Framebuffer scene = Framebuffer.scene(GL.context(), SIZE, SIZE);
             Framebuffer target = new Framebuffer(GL.context(), SIZE, SIZE, Format.RGBA8, null,
                     Sampling.NEAREST_CLAMP)) {
            for (int frame = 0; frame < FRAMES; frame++) {
                CameraPose pose = new CameraPose(0, 100, 0, frame * yawPerFrame, 0, CameraPose.DEFAULT_FOV);
                ViewCamera camera = ViewCamera.perspective(pose, 1, 0.5f, 1000);
                float grey = (frame % 2 == 0 ? EVEN : ODD) / 255f;
                scene.bind();
                glClearColor(grey, grey, grey, 1);
                glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT); // depth 1: the far plane, as the sky's
                taa.draw(scene, target, camera, frame, 1.0 / FRAMES, new DrawStats());
            }
            Image image = target.read();
            return image.channel(SIZE / 2, SIZE / 2, 0);
        }
    }

    @Test
    void aStillViewSettlesToTheMeanOfItsFrames() {
        // the history, unclamped, is the exact mean of the 16 even and 16 odd frames
        assertEquals((EVEN + ODD) / 2.0, settled(0), TOLERANCE);
    }

    @Test
    void aTurningViewClampsTheHistoryToTheFrame() {
        // a pixel of the 8-pixel-wide picture spans 60 / 8 degrees: turning that much a frame moves every pixel by
        // one, twice the motion from which the clamp is whole, so the history is the last (odd) frame's grey
        assertEquals(ODD, settled(CameraPose.DEFAULT_FOV / SIZE), TOLERANCE);
    }
}

package org.openworld.engine.sky.clouds;

import org.joml.Vector3f;
import org.joml.Vector3fc;
import org.joml.Vector4fc;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.environment.CloudPanorama;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.OffscreenState;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Texture2D;
import org.openworld.engine.gl.Uniform;

import static org.lwjgl.opengl.GL11C.*;

/**
 * The volumetric clouds for what cannot march them: the same march as the picture's, from the viewer's eye in every
 * direction, into a panorama in the sky's layout ({@link CloudPanorama}, {@code clouds/panorama.frag}), which the
 * water's reflection reads per sky pixel ({@code clouds/reflection.frag}) and the sky's environment map per texel.
 *
 * <p>Amortised as the picture is: one band of {@link #SIZE}/{@link #BANDS} rows a frame, so a panorama is renewed
 * every {@link #BANDS} frames (0.27 s at 60 frames a second; the eye at 300 m/s moves 80 m meanwhile, a parallax of
 * 2° on clouds 2.5 km overhead, lost in the ripples); and only the hemisphere that can hold clouds: the upper below
 * the layer, the lower above it, both inside. Whole when there is none yet, the settings changed, the eye cut (moved
 * {@link CloudVolumeSystem#CUT_DISTANCE} since the last frame) or crossed into another hemisphere's case. Cost at
 * 128² a hemisphere: 1 024 rays a frame, 1/14 of the picture's march at 1280 × 720 (14 400 rays).
 *
 * <p>Limits: a direction-only map, so a reflection shows the clouds as the eye sees them along the mirrored ray (not
 * from the water's point: 10 m of height over water is 0.2° on clouds 2.5 km up); 1.4° a texel at the horizon, soft
 * where the ripples do not blur it; the environment map follows it at the sky's own refresh.
 */
final class CloudPanoramaMarch {

    /** Texels along a side of each hemisphere's square: 0.7° to 1.4° a texel, finer than the rippled reflection. */
    static final int SIZE = 128;
    /** Bands of rows, one marched per frame: a whole panorama every this many frames. */
    static final int BANDS = 16;

    private final Texture2D panorama;
    private final Framebuffer target;
    private final ShaderProgram march;
    private final Uniform.Vec4 marchLayer;
    private final Uniform.Vec4 marchMotion;
    private final Uniform.Vec2 marchSize;
    private final ShaderProgram reflection;
    private int band;
    /** The hemispheres marched (bit 0 upper, bit 1 lower), or 0 before the first panorama. */
    private int hemispheres;
    private Object settings;
    /** The viewer's eye at the last march. */
    private final Vector3f eye = new Vector3f();

    CloudPanoramaMarch(EngineContext context) {
        panorama = context.own("panorama", Texture2D.empty(context.gl(), 2 * SIZE, SIZE, Format.RGBA16F,
                Sampling.LINEAR_CLAMP));
        target = context.own("panoramaTarget", Framebuffer.onTextures(context.gl(), panorama));
        march = context.own("panoramaProgram", context.shaders().program("clouds/fullscreen.vert",
                "clouds/panorama.frag"));
        march.sampler(CloudPrograms.FIELD);
        march.sampler(CloudPrograms.OPTICS);
        march.sampler(CloudPrograms.DETAIL);
        marchLayer = march.vec4("uLayer");
        marchMotion = march.vec4("uMotion");
        marchSize = march.vec2("uSize");
        reflection = context.own("reflectionProgram", context.shaders().program("clouds/fullscreen.vert",
                "clouds/reflection.frag"));
        reflection.sampler(CloudPrograms.PANORAMA);
    }

    /** The panorama as the world's resource. */
    CloudPanorama resource() {
        return new CloudPanorama(panorama);
    }

    /**
     * Marches this frame's band (or the whole panorama, see the class) for the viewer's eye {@code viewer} (world
     * space, m) between the base's and the top's radii of {@code layer}, with the field, detail and optics already
     * bound; the pass's framebuffer, viewport and tests are given back as they were.
     */
    void march(Vector4fc layer, Vector4fc motion, Object cloudSettings, Vector3fc viewer, double altitude,
               double base, double top, Mesh fullScreen, DrawStats stats) {
        int needed = (altitude < top ? 1 : 0) | (altitude > base ? 2 : 0);
        boolean whole = needed != hemispheres || !cloudSettings.equals(settings)
                || viewer.distance(eye) > CloudVolumeSystem.CUT_DISTANCE;
        try (OffscreenState state = OffscreenState.enter()) {
            target.bind();
            if (whole) {
                glClearColor(0, 0, 0, 1); // no cloud: no light, everything through
                glClear(GL_COLOR_BUFFER_BIT);
            }
            march.use();
            marchLayer.set(layer);
            marchMotion.set(motion);
            marchSize.set(2 * SIZE, SIZE);
            int rows = whole ? SIZE : SIZE / BANDS;
            int y = whole ? 0 : band * rows;
            int from = (needed & 1) != 0 ? 0 : SIZE;
            int to = (needed & 2) != 0 ? 2 * SIZE : SIZE;
            // the full-screen triangle fills the viewport; gl_FragCoord stays the panorama's own texel
            glViewport(from, y, to - from, rows);
            fullScreen.draw(stats);
        }
        band = whole ? 0 : (band + 1) % BANDS;
        hemispheres = needed;
        settings = cloudSettings;
        eye.set(viewer);
    }

    /**
     * Draws the panorama's clouds over the sky's pixels of the water's reflection (the pass's target, bound, its
     * depth on the far plane where no mirrored surface is), blended as the picture's composite.
     */
    void drawReflection(Mesh fullScreen, DrawStats stats) {
        panorama.bind(CloudPrograms.PANORAMA.unit());
        reflection.use();
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glDepthMask(false);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        fullScreen.draw(stats);
        glDisable(GL_BLEND);
        glDepthMask(true);
        glDepthFunc(GL_LESS);
    }
}

package org.openworld.engine.shadow;

import static org.lwjgl.opengl.GL11C.*;
import static org.lwjgl.opengl.GL30C.*;

import org.joml.Vector3fc;
import org.openworld.engine.core.Counter;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.core.Owned;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.World;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.TextureUnits;
import org.openworld.engine.gl.Uniform;
import org.openworld.engine.origin.RenderOrigin;

/**
 * Measures the sun's shadows in the finished picture ({@code shadow.measure}): per pixel, the visibility every lit
 * shader sees and the world point it is seen at, read back and judged by {@link ShadowStatistics} into the counters
 * {@code shadow.flicker}, {@code shadow.flicker-pixels}, {@code shadow.acne} and {@code shadow.acne-pixels}.
 *
 * <p>Called once per frame in the OVERLAY pass, when the scene target holds the picture and its depth. The read-back
 * stalls the GPU and the acne's ray marches cost milliseconds: a tool for quality runs, not for timings.
 *
 * <p>Limits: the world point is rebuilt from the 24-bit depth, whose rounding grows with the square of the distance
 * (6 cm at 1 km, 1.5 m at 5 km with the camera's 0.5 m near plane); the statistics' tolerances grow with distance
 * for that reason. Pixels on a silhouette take a normal from two surfaces. With no {@link HeightField} in the world
 * the ground is taken as flat at sea level.
 */
final class ShadowProbe {
    /** The counters: the flicker's mean and its pixels, the acne's fraction and its pixels. */
    private static final Counter FLICKER = Counter.of("shadow", "flicker");
    private static final Counter FLICKER_PIXELS = Counter.of("shadow", "flicker-pixels");
    private static final Counter ACNE = Counter.of("shadow", "acne");
    private static final Counter ACNE_PIXELS = Counter.of("shadow", "acne-pixels");

    private static final TextureUnits UNITS = new TextureUnits();
    /** The copied depth, the previous frame's points. */
    private static final TextureUnits.Sampler DEPTH = UNITS.add("sceneDepth");
    private static final TextureUnits.Sampler POINTS = UNITS.add("points");

    private final GlContext gl;
    /** The system's owner, which closes the targets as they are re-made and everything at the end. */
    private final Owned owned;
    private final Mesh fullScreen;
    private final ShaderProgram program;
    private final Uniform.Int revisit;
    private final ShadowStatistics statistics = new ShadowStatistics();
    /** The scene's depth, copied: the scene's own is attached to the framebuffer bound in OVERLAY. */
    private Framebuffer depthCopy;
    /** The probe's output, one RGBA32F texel per pixel of the picture: this frame's, and the last frame's. */
    private Framebuffer probed;
    private Framebuffer lastProbed;
    /** This frame's visibility at the last frame's points. */
    private Framebuffer revisited;
    private boolean haveLast;
    private float[] pixels;
    private float[] revisitedPixels;

    ShadowProbe(EngineContext context) {
        this.gl = context.gl();
        this.owned = context.owned();
        fullScreen = context.own("probe.fullScreen", Mesh.fullScreenTriangle(gl));
        program = context.own("probe", context.shaders().program("shadow/probe.vert", "shadow/probe.frag"));
        program.sampler(DEPTH);
        program.sampler(POINTS);
        revisit = program.int1("revisit");
    }

    /** Measures this frame's picture into the world's {@link Counters}; leaves the scene target bound. */
    void measure(RenderContext context) {
        Framebuffer scene = context.target();
        fit(scene.width(), scene.height());
        // 1. the scene's depth into our own texture (nearest: depth is not to be blended)
        glBindFramebuffer(GL_READ_FRAMEBUFFER, scene.id());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, depthCopy.id());
        glBlitFramebuffer(0, 0, scene.width(), scene.height(), 0, 0, scene.width(), scene.height(),
                GL_DEPTH_BUFFER_BIT, GL_NEAREST);
        // 2. per pixel: visibility and world point (probe.frag), every pixel written, read back bottom row first
        glDisable(GL_DEPTH_TEST);
        program.use();
        depthCopy.depth().bind(DEPTH.unit());
        draw(probed, false, context, pixels);
        // 3. the last frame's points under this frame's maps: what changed there is the maps' flicker
        if (haveLast) {
            lastProbed.color().bind(POINTS.unit());
            draw(revisited, true, context, revisitedPixels);
        }
        // 4. judged against the last frame and the height field, into the counters
        count(context, haveLast ? revisitedPixels : null);
        Framebuffer swap = lastProbed;
        lastProbed = probed;
        probed = swap;
        haveLast = true;
        // 5. the scene target again, with the state the engine expects after any system
        scene.bind();
        glDisable(GL_DEPTH_TEST);
        glDepthMask(true);
        glUseProgram(0);
    }

    private void draw(Framebuffer target, boolean revisiting, RenderContext context, float[] out) {
        target.bind();
        revisit.set(revisiting ? 1 : 0);
        fullScreen.draw(context.stats());
        glBindFramebuffer(GL_READ_FRAMEBUFFER, target.id());
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        glReadPixels(0, 0, target.width(), target.height(), GL_RGBA, GL_FLOAT, out);
    }

    private void count(RenderContext context, float[] lastPointsNow) {
        World world = context.world();
        Counters counters = world.resource(Counters.class);
        // the probe's points are from the render origin, as everything the GPU holds: so are the eye and the ground
        RenderOrigin origin = world.resource(RenderOrigin.class);
        Vector3fc eye = context.camera().positionFrom(origin.x(), origin.z());
        Vector3fc toSun = world.findResource(Sun.class).orElse(Sun.NOON).direction();
        HeightField field = world.findResource(HeightField.class).orElse(HeightField.FLAT);
        HeightField ground = (x, z) -> field.heightAt(x + origin.x(), z + origin.z());
        ShadowStatistics.Measures measures = statistics.measure(pixels, lastPointsNow, probed.width(), eye, toSun,
                ground, highestCaster(CasterHeights.of(world)));
        measures.flicker().ifPresent(flicker -> {
            counters.put(FLICKER, flicker.mean());
            counters.put(FLICKER_PIXELS, flicker.pixels());
        });
        counters.put(ACNE, measures.acne().fraction());
        counters.put(ACNE_PIXELS, measures.acne().pixels());
    }

    /**
     * The highest point of everything the culling system knows (the tops of the bounds trees), metres; above it the
     * sun's ray is free. Unbounded when nothing is known: the march then runs its whole reach.
     */
    private static double highestCaster(CasterHeights casters) {
        return casters.high() > Double.NEGATIVE_INFINITY ? casters.high() : Double.POSITIVE_INFINITY;
    }

    /** (Re)makes the targets and the read-back arrays when the picture's size changed: not every frame. */
    private void fit(int width, int height) {
        if (probed != null && probed.width() == width && probed.height() == height) {
            return;
        }
        depthCopy = owned.replace("probe.depth", depthCopy,
                new Framebuffer(gl, width, height, null, Format.DEPTH24_STENCIL8, Sampling.NEAREST_CLAMP));
        probed = owned.replace("probe.points", probed, points(width, height));
        lastProbed = owned.replace("probe.last-points", lastProbed, points(width, height));
        revisited = owned.replace("probe.revisited", revisited, points(width, height));
        haveLast = false;
        pixels = new float[width * height * ShadowStatistics.CHANNELS];
        revisitedPixels = new float[pixels.length];
    }

    /** One RGBA32F texel per pixel: a visibility and a world point, read back exactly. */
    private Framebuffer points(int width, int height) {
        return new Framebuffer(gl, width, height, Format.RGBA32F, null, Sampling.NEAREST_CLAMP);
    }
}

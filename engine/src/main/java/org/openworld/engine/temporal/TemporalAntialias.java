package org.openworld.engine.temporal;

import static org.lwjgl.opengl.GL11C.GL_BLEND;
import static org.lwjgl.opengl.GL11C.GL_CULL_FACE;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.GL_STENCIL_TEST;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.glBindFramebuffer;

import org.joml.Matrix4d;
import org.joml.Matrix4f;
import org.openworld.engine.core.Owned;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.ShaderLibrary;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Texture2D;
import org.openworld.engine.gl.TextureUnits;
import org.openworld.engine.gl.Uniform;

/**
 * The temporal anti-aliasing pass ({@code shaders/temporal/taa.frag}): each frame drawn with the projection moved by
 * {@link Jitter}'s offset, then blended into a history reprojected from depth and the last frame's view-projection.
 * A run of history lasts while the engine draws the pass frame after frame; a frame without it (the method switched,
 * the size changed) starts a new run, whose first frame is drawn without jitter and kept as it is. See the package's
 * page for the method, its cost and its limits.
 */
public final class TemporalAntialias implements AutoCloseable {

    private static final TextureUnits UNITS = new TextureUnits();
    private static final TextureUnits.Sampler SCENE = UNITS.add("scene");
    private static final TextureUnits.Sampler DEPTH = UNITS.add("depth");
    private static final TextureUnits.Sampler HISTORY = UNITS.add("history");

    private final GlContext gl;
    private final Owned owned = new Owned("temporal");
    private final Mesh fullScreen;
    private final ShaderProgram program;
    private final Uniform.Mat4 reprojection;
    private final Uniform.Float weight;
    /** Two histories, read and written in turn: {@code histories[latest]} holds the last output. */
    private final Texture2D[] histories = new Texture2D[2];
    /** Per history, the target that writes it and the anti-aliased picture at once (outputs 0 and 1). */
    private final Framebuffer[] writes = new Framebuffer[2];
    /** The picture's texture the {@link #writes} hold: made again when the engine's target is. */
    private Texture2D picture;
    private int latest;
    /** Frames in the current run before the next one; 0 when the next frame starts a run. */
    private long run;
    /** The engine frame last drawn, so that a frame skipped ends the run. */
    private long lastFrame = Long.MIN_VALUE;
    private final Matrix4d previous = new Matrix4d();

    public TemporalAntialias(GlContext gl, ShaderLibrary shaders) {
        this.gl = gl;
        try {
            fullScreen = owned.own("fullScreen", Mesh.fullScreenTriangle(gl));
            program = owned.own("taa", shaders.program("temporal/taa.vert", "temporal/taa.frag"));
            program.sampler(SCENE);
            program.sampler(DEPTH);
            program.sampler(HISTORY);
            reprojection = program.mat4("reprojection");
            weight = program.float1("weight");
        } catch (RuntimeException e) {
            owned.close();
            throw e;
        }
    }

    /** Frames of history the engine's frame {@code frame} will be blended with: 0 when it starts a run. */
    private long runBefore(long frame) {
        return frame == lastFrame + 1 ? run : 0;
    }

    /**
     * The viewer's camera for engine frame {@code frame}, jittered for a target of {@code scene}'s size in a cycle of
     * {@code cycle} offsets ({@code antialias.samples}).
     */
    public ViewCamera jittered(ViewCamera camera, long frame, int cycle, Framebuffer scene) {
        return Jitter.apply(camera, runBefore(frame), cycle, scene.width(), scene.height());
    }

    /**
     * Blends {@code scene} (drawn with {@link #jittered}) into the history and, in the same draw, into
     * {@code target} (the scene's size), then binds no framebuffer.
     *
     * @param camera    the viewer's camera without jitter: its view-projection reprojects the next frame
     * @param minWeight the least share of a frame in the result once the run is long enough ({@code antialias.blend})
     */
    public void draw(Framebuffer scene, Framebuffer target, ViewCamera camera, long frame, double minWeight,
                     DrawStats stats) {
        long n = runBefore(frame);
        if (histories[0] == null || histories[0].width() != scene.width()
                || histories[0].height() != scene.height()) {
            for (int i = 0; i < histories.length; i++) {
                histories[i] = owned.replace("history" + i, histories[i], Texture2D.empty(gl, scene.width(),
                        scene.height(), Format.RGBA16F, Sampling.LINEAR_CLAMP));
            }
            n = 0;
            picture = null; // the writes hold the old histories
        }
        if (picture != target.color()) {
            picture = target.color();
            for (int i = 0; i < writes.length; i++) {
                writes[i] = owned.replace("write" + i, writes[i],
                        Framebuffer.onTextures(gl, histories[i], picture));
            }
        }
        // in double from the exact view: far from the origin a float view-projection is metres off
        Matrix4d now = new Matrix4d().set(camera.projection()).mul(camera.exactView());
        writes[1 - latest].bind();
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_STENCIL_TEST);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        program.use();
        // NDC now -> clip then; computed in double, as it is near the identity for a small motion
        reprojection.set(new Matrix4f().set(new Matrix4d(previous).mul(new Matrix4d(now).invert())));
        weight.set(n == 0 ? 1f : (float) Math.max(minWeight, 1.0 / (n + 1)));
        scene.color().bind(SCENE.unit());
        scene.depth().bind(DEPTH.unit());
        histories[latest].bind(HISTORY.unit());
        fullScreen.draw(stats);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        latest = 1 - latest;
        previous.set(now);
        run = n + 1;
        lastFrame = frame;
    }

    @Override
    public void close() {
        owned.close();
    }
}

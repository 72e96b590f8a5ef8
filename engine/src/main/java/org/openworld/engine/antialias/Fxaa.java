package org.openworld.engine.antialias;

import static org.lwjgl.opengl.GL11C.GL_BLEND;
import static org.lwjgl.opengl.GL11C.GL_CULL_FACE;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.GL_STENCIL_TEST;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.glBindFramebuffer;

import org.openworld.engine.core.Owned;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.ShaderLibrary;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.TextureUnits;
import org.openworld.engine.gl.Uniform;

/**
 * The FXAA pass ({@code shaders/antialias/fxaa.frag}): one full-screen triangle that reads the finished scene
 * target's colour texel by texel and writes the anti-aliased picture into a target of the same size. The engine runs
 * it after every pass, before the stretch to the picture's size below {@code engine.render-scale} 1, so the edges
 * are found at the resolution they were drawn at. See the package's page for the method, its cost and its limits.
 */
public final class Fxaa implements AutoCloseable {

    private static final TextureUnits UNITS = new TextureUnits();
    /** The scene's colour while the pass draws. */
    private static final TextureUnits.Sampler SCENE = UNITS.add("scene");

    private final Owned owned = new Owned("antialias");
    private final Mesh fullScreen;
    private final ShaderProgram program;
    private final Uniform.Float subpixel;

    public Fxaa(GlContext gl, ShaderLibrary shaders) {
        try {
            fullScreen = owned.own("fullScreen", Mesh.fullScreenTriangle(gl));
            program = owned.own("fxaa", shaders.program("antialias/fxaa.vert", "antialias/fxaa.frag"));
            program.sampler(SCENE);
            subpixel = program.float1("subpixel");
        } catch (RuntimeException e) {
            owned.close();
            throw e;
        }
    }

    /** Draws {@code scene}'s colour anti-aliased into {@code target} (the same size), then binds no framebuffer. */
    public void draw(Framebuffer scene, Framebuffer target, AntialiasSettings settings, DrawStats stats) {
        target.bind();
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_STENCIL_TEST);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        program.use();
        subpixel.set((float) settings.subpixel());
        scene.color().bind(SCENE.unit());
        fullScreen.draw(stats);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    @Override
    public void close() {
        owned.close();
    }
}

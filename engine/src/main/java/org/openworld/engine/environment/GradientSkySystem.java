package org.openworld.engine.environment;

import static org.lwjgl.opengl.GL11C.*;

import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.ShaderProgram;

/**
 * A sky for worlds without an atmosphere model: a gradient from the fog colour at the horizon to blue at the zenith,
 * with a glow around the sun, all scaled by the world's light so it darkens with the day. The sky system of paper
 * section 3.1 replaces it.
 *
 * <p>Drawn as one full-screen triangle at the far plane with the depth test {@code LEQUAL} and no depth write, so it
 * fills exactly the pixels nothing else covered, whether it is drawn before or after the ground: no order needed.
 */
public final class GradientSkySystem implements EngineSystem {

    private ShaderProgram program;
    private Mesh fullScreen;

    @Override
    public SystemSpec spec() {
        return SystemSpec.named("sky").reads(Sun.class, Fog.class).draws(Pass.MAIN);
    }

    @Override
    public void init(EngineContext context) {
        program = context.shaders().program("environment/gradient-sky.vert", "environment/gradient-sky.frag");
        fullScreen = new Mesh(context.gl(), new float[] {-1, -1, 3, -1, -1, 3}, new int[] {0, 1, 2},
                new Mesh.Attribute(0, 2));
    }

    @Override
    public void render(Pass pass, RenderContext context) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glDepthMask(false);
        program.use();
        fullScreen.draw(context.stats());
        glDepthMask(true);
        glDepthFunc(GL_LESS);
    }

    @Override
    public void close() {
        if (fullScreen != null) {
            fullScreen.close();
        }
        if (program != null) {
            program.close();
        }
    }
}

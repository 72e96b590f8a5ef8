package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glEnable;

import java.util.List;
import org.joml.Vector3d;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.Layer;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.gl.Image;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.ShaderProgram;

/**
 * The environment map the sky draws into a cube holds the sky the CPU computes, in every face: read back through
 * {@code common/environment.glsl} in four directions on three faces (+Y, +X, −Z, −X) and compared with
 * {@link SkyReference}. A wrong face axis or a missing draw shows as a wrong colour in one column.
 */
@GlTest
class EnvironmentMapTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final double ALTITUDE = 300;

    /** Draws the environment map's radiance in four directions after the sky has drawn it. */
    static final class Probe implements EngineSystem {
        private ShaderProgram program;
        private Mesh triangle;

        @Override
        public SystemSpec spec() {
            return SystemSpec.named("probe").layer(Layer.OVER_OPAQUE).draws(Pass.MAIN);
        }

        @Override
        public void init(EngineContext context) {
            program = context.shaders().program("test/fullscreen.vert", "test/sky/environment-probe.frag");
            triangle = GlTestSupport.fullScreenTriangle(context.gl());
        }

        @Override
        public void render(Pass pass, RenderContext context) {
            glDisable(GL_DEPTH_TEST);
            program.use();
            triangle.draw(context.stats());
            glEnable(GL_DEPTH_TEST);
        }

        @Override
        public void close() {
            triangle.close();
            program.close();
        }
    }

    @Test
    void cubeFacesHoldTheSkyOfTheirDirections() {
        Vector3d[] directions = {
            new Vector3d(0, 1, 0),
            new Vector3d(Math.cos(Math.toRadians(20)), Math.sin(Math.toRadians(20)), 0),
            new Vector3d(0, Math.sin(Math.toRadians(45)), -Math.cos(Math.toRadians(45))),
            new Vector3d(-Math.cos(Math.toRadians(10)), Math.sin(Math.toRadians(10)), 0)};
        try (Engine engine = GlTestSupport.engine(GL.context(), 32, 8, List.of("clouds.cover=0"), new SkySystem(),
                new Probe())) {
            engine.world().setResource(new TimeOfDay(16, 0));
            engine.world().resource(Camera.class).setPose(new CameraPose(0, ALTITUDE, 0, 0, 0, 60));
            engine.update();
            engine.render();
            Image image = engine.readImage();
            AtmosphereTables tables = AtmosphereTables.build(AtmosphereSettings.DEFAULTS);
            Vector3f s = engine.world().resource(Sun.class).direction().get(new Vector3f());
            Vector3d toSun = new Vector3d(s.x, s.y, s.z);
            for (int i = 0; i < directions.length; i++) {
                Vector3d expected = SkyReference.radiance(tables, directions[i], toSun, ALTITUDE).mul(4 * 255);
                for (int c = 0; c < 3; c++) {
                    double want = Math.min(255, expected.get(c));
                    assertEquals(want, image.channel(8 * i + 4, 4, c), 3 + 0.08 * want,
                            "direction " + directions[i] + " channel " + c);
                }
            }
        }
    }
}

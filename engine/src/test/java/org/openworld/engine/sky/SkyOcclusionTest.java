package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.lwjgl.opengl.GL11C.*;
import static org.lwjgl.opengl.GL15C.GL_QUERY_RESULT;
import static org.lwjgl.opengl.GL15C.GL_SAMPLES_PASSED;
import static org.lwjgl.opengl.GL15C.glBeginQuery;
import static org.lwjgl.opengl.GL15C.glDeleteQueries;
import static org.lwjgl.opengl.GL15C.glEndQuery;
import static org.lwjgl.opengl.GL15C.glGenQueries;
import static org.lwjgl.opengl.GL15C.glGetQueryObjecti;

import java.util.List;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
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
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.ShaderProgram;

/**
 * The sky is shaded only where no opaque surface covers it: an opaque test system covers the left part of the
 * picture with a surface nearer than the far plane and then opens an occlusion query (samples that pass the depth
 * test), and a system drawn over the opaque picture closes it, so the query counts the sky's samples alone. They
 * must be exactly the pixels left uncovered: none under a surface over the whole view, every pixel with none. A sky
 * drawn before the opaque systems is counted as 0 wherever some pixel is uncovered, and one drawn without the depth
 * test as every pixel wherever some is covered.
 */
@GlTest
class SkyOcclusionTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int WIDTH = 64;
    static final int HEIGHT = 36;

    /**
     * Covers the first {@code columns} columns at depth 0.5 (clip z 0), then starts counting samples. Named to sort
     * after "sky", so only the sky's declaration puts the sky behind it.
     */
    static final class Cover implements EngineSystem {
        private final int columns;
        private ShaderProgram program;
        private Mesh triangle;
        private int query;

        Cover(int columns) {
            this.columns = columns;
        }

        @Override
        public SystemSpec spec() {
            return SystemSpec.named("wall").draws(Pass.MAIN);
        }

        @Override
        public void init(EngineContext context) {
            program = context.own("program", context.shaders().program("test/fullscreen.vert", "test/solid.frag"));
            triangle = context.own("triangle", GlTestSupport.fullScreenTriangle(context.gl()));
            query = glGenQueries();
        }

        @Override
        public void render(Pass pass, RenderContext context) {
            program.use();
            program.vec4("uColor").set(0.2f, 0.5f, 0.1f, 1);
            glEnable(GL_DEPTH_TEST);
            glEnable(GL_SCISSOR_TEST);
            glScissor(0, 0, columns, HEIGHT);
            triangle.draw(context.stats());
            glDisable(GL_SCISSOR_TEST);
            glBeginQuery(GL_SAMPLES_PASSED, query);
        }

        @Override
        public void close() {
            glDeleteQueries(query);
        }
    }

    /** Stops counting once the opaque picture and its background are drawn, and keeps the count. */
    static final class Counter implements EngineSystem {
        @Override
        public SystemSpec spec() {
            return SystemSpec.named("counter").layer(Layer.OVER_OPAQUE).draws(Pass.MAIN);
        }

        @Override
        public void render(Pass pass, RenderContext context) {
            glEndQuery(GL_SAMPLES_PASSED);
        }
    }

    @ParameterizedTest
    @ValueSource(ints = {WIDTH, WIDTH / 4, 0})
    void theSkyIsShadedOnlyWhereNothingOpaqueIs(int covered) {
        Cover cover = new Cover(covered);
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT, List.of(), new SkySystem(), cover,
                new Counter())) {
            List<String> order = engine.order().drawOrder(Pass.MAIN).stream().map(s -> s.spec().name()).toList();
            assertEquals(List.of("wall", "sky", "counter"), order, "the sky is drawn after the opaque systems");
            engine.world().resource(Camera.class).setPose(new CameraPose(0, 300, 0, 0, 10, 60));
            engine.update();
            engine.render();
            int samples = glGetQueryObjecti(cover.query, GL_QUERY_RESULT);
            assertEquals((WIDTH - covered) * HEIGHT, samples,
                    "samples the sky shaded with " + covered + " of " + WIDTH + " columns covered");
        }
    }
}

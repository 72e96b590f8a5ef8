package org.openworld.engine.gl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.glDisable;

import java.util.List;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector3fc;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;
import org.openworld.engine.GlTest;
import org.openworld.engine.HeadlessGl;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.Engine;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.PassOwner;
import org.openworld.engine.core.PassView;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.core.World;
import org.openworld.engine.environment.Exposure;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.environment.TimeOfDay;

/**
 * The frame block end to end: the engine fills it from the world, a shader ({@code shaders/test/frame/probe.frag})
 * writes each member back out as a colour, and the pixels must carry the Java-side values. A Java field order or
 * offset that differs from the GLSL block shows up as a wrong column.
 */
@GlTest
class FrameUniformsTest {

    /** 9 columns of 8 pixels, one block member (or check) per column. */
    static final int WIDTH = 72;
    static final int HEIGHT = 16;
    /** RGBA8 keeps a value in 0..1 to half a step of 1/255; allow one step. */
    static final double TOLERANCE = 1.0;

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    /** Draws the probe shader over the whole scene target. */
    static final class ProbeSystem implements EngineSystem {
        Vector3fc point = new Vector3f();
        private ShaderProgram program;
        private Uniform.Vec3 probePoint;
        private Mesh triangle;

        @Override
        public SystemSpec spec() {
            return SystemSpec.named("frame-probe").draws(Pass.MAIN);
        }

        @Override
        public void init(EngineContext context) {
            program = context.shaders().program("test/fullscreen.vert", "test/frame/probe.frag");
            probePoint = program.vec3("uProbePoint");
            triangle = GlTestSupport.fullScreenTriangle(context.gl());
        }

        @Override
        public void render(Pass pass, RenderContext context) {
            glDisable(GL_DEPTH_TEST);
            program.use();
            probePoint.set(point);
            triangle.draw(context.stats());
        }

        @Override
        public void close() {
            triangle.close();
            program.close();
        }
    }

    private static void assertColumn(Image image, int column, float r, float g, float b, float a) {
        float[] expected = {r, g, b, a};
        for (int c = 0; c < 4; c++) {
            assertTrue(expected[c] >= 0 && expected[c] <= 1, "test value out of 0..1: column " + column + " channel " + c);
            int x = column * 8 + 4;
            double got = image.channel(x, HEIGHT / 2, c);
            assertEquals(expected[c] * 255, got, TOLERANCE, "column " + column + ", channel " + "rgba".charAt(c));
        }
    }

    @Test
    void everyMemberOfTheBlockArrivesAtTheShader() {
        ProbeSystem probe = new ProbeSystem();
        CameraPose pose = new CameraPose(120, 250, 730, 30, -10, 60);
        Vector3f sunDir = new Vector3f(0.3f, 0.5f, -0.8f).normalize();
        Vector3f sunColor = new Vector3f(1.2f, 0.9f, 0.6f);
        Vector3f ambient = new Vector3f(0.25f, 0.35f, 0.45f);
        Exposure exposure = new Exposure(3.25f, 0.375f);
        double hours = 15.25;
        int updates = 6;

        Image image;
        Vector4f expectedNdc;
        double simTime;
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT, probe)) {
            engine.world().resource(Camera.class).setPose(pose);
            engine.world().setResource(new Sun(sunDir, sunColor, ambient));
            engine.world().setResource(exposure);
            engine.world().setResource(new TimeOfDay(hours, 0));
            ViewCamera camera = engine.world().resource(Camera.class).view((float) WIDTH / HEIGHT);
            // A point 100 m ahead of the eye, a little right and below, so it projects inside the picture.
            probe.point = new Matrix4f(camera.view()).invert().transformPosition(new Vector3f(10, -5, -100));
            expectedNdc = new Matrix4f(camera.viewProjection()).transform(new Vector4f(probe.point, 1));
            expectedNdc.div(expectedNdc.w);
            for (int i = 0; i < updates; i++) {
                engine.update();
            }
            engine.render(); // frame 0
            engine.render(); // frame 1: the one read back
            image = engine.readImage();
            simTime = updates * engine.settings().get(EngineSettings.class).step();
            // doubles: the same sum read back, equal to round-off
            assertEquals(simTime, engine.simTime(), 1e-12);
        }

        assertColumn(image, 0, WIDTH / 256f, HEIGHT / 256f, 16f / WIDTH, 16f / HEIGHT);
        assertColumn(image, 1, (float) pose.x() / 1000, (float) pose.y() / 1000, (float) pose.z() / 1000, Camera.NEAR);
        assertColumn(image, 2, sunDir.x * 0.5f + 0.5f, sunDir.y * 0.5f + 0.5f, sunDir.z * 0.5f + 0.5f,
                Camera.FAR / 40000);
        assertColumn(image, 3, sunColor.x * 0.5f, sunColor.y * 0.5f, sunColor.z * 0.5f, 1);
        assertColumn(image, 4, ambient.x, ambient.y, ambient.z, 1);
        assertColumn(image, 5, exposure.scale() / 8, exposure.scotopic(), 0, 1);
        assertColumn(image, 6, (float) (simTime * 5), (float) hours / 24, 1 / 8f, 1);
        float ndcX = expectedNdc.x * 0.5f + 0.5f;
        float ndcY = expectedNdc.y * 0.5f + 0.5f;
        assertColumn(image, 7, ndcX, ndcY, ndcX, ndcY);
        assertColumn(image, 8, expectedNdc.z * 0.5f + 0.5f, 1, 0, 1);
        assertEquals(0, GL.context().objects().live(), "live GL objects after close: " + GL.context().objects());
    }

    /**
     * Owns a pass and gives it one camera at a fixed eye, far from the viewer's, with its own small target; draws
     * nothing itself.
     */
    static final class EyeOwner implements EngineSystem, PassOwner {
        final Pass owned;
        final Vector3f eye;
        Framebuffer target;

        EyeOwner(Pass owned, Vector3f eye) {
            this.owned = owned;
            this.eye = eye;
        }

        @Override
        public SystemSpec spec() {
            return SystemSpec.named("owner-" + owned.label()).draws(Pass.OVERLAY);
        }

        @Override
        public void init(EngineContext context) {
            target = context.own(new Framebuffer(context.gl(), 16, 4, Format.RGBA8, Format.DEPTH32F,
                    Sampling.NEAREST_CLAMP));
        }

        @Override
        public Pass ownedPass() {
            return owned;
        }

        @Override
        public List<PassView> passViews(World world, PassView viewer) {
            ViewCamera c = viewer.camera();
            return List.of(new PassView(new ViewCamera(c.view(), c.projection(), eye, c.near(), c.far()), target));
        }

        @Override
        public void render(Pass pass, RenderContext context) {
        }
    }

    /** Draws the two eyes (shaders/test/frame/eyes.frag) in the shadow and the reflection pass. */
    static final class EyesProbe implements EngineSystem {
        private ShaderProgram program;
        private Mesh triangle;

        @Override
        public SystemSpec spec() {
            return SystemSpec.named("eyes").draws(Pass.SHADOW, Pass.REFLECTION);
        }

        @Override
        public void init(EngineContext context) {
            program = context.own(context.shaders().program("test/fullscreen.vert", "test/frame/eyes.frag"));
            triangle = context.own(GlTestSupport.fullScreenTriangle(context.gl()));
        }

        @Override
        public void render(Pass pass, RenderContext context) {
            glDisable(GL_DEPTH_TEST);
            program.use();
            triangle.draw(context.stats());
        }
    }

    @Test
    void inTheShadowAndReflectionPassesViewerPosIsTheViewersEyeAndCameraPosThePassCameras() {
        CameraPose pose = new CameraPose(120, 250, 730, 30, -10, 60);
        Vector3f sunEye = new Vector3f(900, 800, 100);
        Vector3f mirrorEye = new Vector3f(120, 40, 730);
        EyeOwner shadow = new EyeOwner(Pass.SHADOW, sunEye);
        EyeOwner mirror = new EyeOwner(Pass.REFLECTION, mirrorEye);
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT, shadow, mirror, new EyesProbe())) {
            engine.world().resource(Camera.class).setPose(pose);
            engine.render();
            for (EyeOwner owner : List.of(shadow, mirror)) {
                Image image = owner.target.read();
                String pass = owner.owned.label();
                Vector3f[] expected = {new Vector3f((float) pose.x(), (float) pose.y(), (float) pose.z()), owner.eye};
                for (int half = 0; half < 2; half++) {
                    for (int c = 0; c < 3; c++) {
                        assertEquals(expected[half].get(c) / 1000 * 255, image.channel(4 + 8 * half, 2, c), TOLERANCE,
                                pass + (half == 0 ? " viewerPos" : " cameraPos") + ", component " + "xyz".charAt(c));
                    }
                }
            }
        }
        assertEquals(0, GL.context().objects().live(), "live GL objects after close: " + GL.context().objects());
    }
}

package org.openworld.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.glColorMask;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL15C.GL_STATIC_DRAW;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.function.UnaryOperator;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.bench.FrameRecord;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.Counter;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.PassOwner;
import org.openworld.engine.core.PassView;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemOrderException;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.core.World;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.GpuBuffer;
import org.openworld.engine.gl.Image;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Uniform;

/** The frame loop on real GL: pass order, pass cameras, frame records, switching systems off, fixed steps, cleanup. */
@GlTest
class EngineTest {

    static final int SIZE = 64;

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    /** One render call as a system saw it. */
    record Call(String system, Pass pass, ViewCamera camera, Framebuffer target) {
    }

    /**
     * A system that draws one mesh in one flat colour in each of its passes and logs every lifecycle call.
     */
    static class Drawing implements EngineSystem {
        final SystemSpec spec;
        final List<String> log;
        final List<Call> calls;
        final Function<GlContext, Mesh> meshFactory;
        final float[] color;
        int inits;
        int updates;
        boolean closed;
        private ShaderProgram program;
        private Uniform.Vec4 colorUniform;
        private Mesh mesh;

        Drawing(SystemSpec spec, List<String> log, List<Call> calls, Function<GlContext, Mesh> meshFactory,
                float... color) {
            this.spec = spec;
            this.log = log;
            this.calls = calls;
            this.meshFactory = meshFactory;
            this.color = color;
        }

        @Override
        public SystemSpec spec() {
            return spec;
        }

        @Override
        public void init(EngineContext context) {
            inits++;
            program = context.shaders().program("test/fullscreen.vert", "test/solid.frag");
            colorUniform = program.vec4("uColor");
            mesh = meshFactory.apply(context.gl());
        }

        @Override
        public void update(World world, double step) {
            updates++;
            log.add("update " + spec.name());
        }

        @Override
        public void render(Pass pass, RenderContext context) {
            log.add(pass.label() + " " + spec.name());
            calls.add(new Call(spec.name(), pass, context.camera(), context.target()));
            glDisable(GL_DEPTH_TEST);
            program.use();
            colorUniform.set(color[0], color[1], color[2], 1);
            mesh.draw(context.stats());
        }

        @Override
        public void close() {
            closed = true;
            log.add("close " + spec.name());
            mesh.close();
            program.close();
        }
    }

    /** The sun's camera: an orthographic box looking down, as a shadow system would set it. */
    static final ViewCamera SUN_CAMERA = new ViewCamera(
            new Matrix4f().lookAt(0, 500, 0, 0, 0, 0, 0, 0, -1), new Matrix4f().ortho(-100, 100, -100, 100, 1, 1000),
            new Vector3f(0, 500, 0), 1, 1000);

    final List<String> log = new ArrayList<>();
    final List<Call> calls = new ArrayList<>();

    /**
     * Owns a pass the way the shadow and water systems do: gives its camera (from the viewer's) and a small target of
     * its own, or nothing while {@code skip} is set.
     */
    static class Owner extends Drawing implements PassOwner {
        final Pass owned;
        final UnaryOperator<ViewCamera> camera;
        Framebuffer target;
        boolean skip;
        /** The viewer's camera of every passViews call, in order. */
        final List<ViewCamera> viewers = new ArrayList<>();
        /** How many views (cascades) the pass is drawn with; the i-th gets the owner's camera moved up by i metres. */
        int views = 1;

        Owner(SystemSpec spec, Pass owned, UnaryOperator<ViewCamera> camera, List<String> log, List<Call> calls,
              Function<GlContext, Mesh> meshFactory, float... color) {
            super(spec, log, calls, meshFactory, color);
            this.owned = owned;
            this.camera = camera;
        }

        @Override
        public void init(EngineContext context) {
            super.init(context);
            target = new Framebuffer(context.gl(), 16, 16, Format.RGBA8, Format.DEPTH32F,
                    Sampling.NEAREST_CLAMP);
        }

        @Override
        public Pass ownedPass() {
            return owned;
        }

        @Override
        public List<PassView> passViews(World world, PassView viewer) {
            viewers.add(viewer.camera());
            if (skip) {
                return List.of();
            }
            List<PassView> list = new ArrayList<>();
            for (int i = 0; i < views; i++) {
                ViewCamera c = camera.apply(viewer.camera());
                list.add(new PassView(i == 0 ? c : new ViewCamera(c.view(), c.projection(),
                        new Vector3f(c.position()).add(0, i, 0), c.near(), c.far()), target, views > 1 ? i : -1));
            }
            return list;
        }

        @Override
        public void close() {
            super.close();
            target.close();
        }
    }

    /** Owns SHADOW with the sun's camera and reports a counter. */
    final Owner shadow = new Owner(SystemSpec.named("shadow").draws(Pass.SHADOW), Pass.SHADOW, viewer -> SUN_CAMERA,
            log, calls, GlTestSupport::quarterQuad, 0, 0, 0) {
        @Override
        public void update(World world, double step) {
            super.update(world, step);
            world.resource(Counters.class).put(Counter.of("shadow", "casters"), 3);
        }
    };
    /** Owns REFLECTION with the viewer mirrored in y = 0. */
    final Owner mirror = new Owner(SystemSpec.named("mirror").draws(Pass.REFLECTION), Pass.REFLECTION,
            viewer -> new ViewCamera(new Matrix4f(viewer.view()).scale(1, -1, 1), viewer.projection(),
                    new Vector3f(viewer.position()).mul(1, -1, 1), viewer.near(), viewer.far()),
            log, calls, GlTestSupport::fullScreenTriangle, 1, 1, 1);
    final Drawing terrain = new Drawing(SystemSpec.named("terrain").draws(Pass.MAIN),
            log, calls, GlTestSupport::fullScreenTriangle, 0, 1, 0);
    /** Alphabetically before terrain, but declared after it: draws blue over terrain's lower-left quarter. */
    final Drawing decals = new Drawing(SystemSpec.named("decals").after("terrain").draws(Pass.MAIN),
            log, calls, GlTestSupport::quarterQuad, 0, 0, 1) {
        @Override
        public void render(Pass pass, RenderContext context) {
            super.render(pass, context);
            context.world().resource(Counters.class).add(Counter.of("decals", "drawn"), 1);
        }
    };
    /** Draws red over the lower-left quarter after everything else. */
    final Drawing hud = new Drawing(SystemSpec.named("hud").draws(Pass.OVERLAY),
            log, calls, GlTestSupport::quarterQuad, 1, 0, 0);

    private Engine engineWithAllPasses() {
        Engine engine = GlTestSupport.engine(GL.context(), SIZE, SIZE, hud, decals, terrain, mirror, shadow);
        engine.world().resource(Camera.class).setPose(new CameraPose(10, 20, 30, 45, -5, 60));
        return engine;
    }

    private static String rgb(Image image, int x, int y) {
        return image.channel(x, y, 0) + "," + image.channel(x, y, 1) + "," + image.channel(x, y, 2);
    }

    @Test
    void passesRunInOrderWithSystemsInResolvedOrder() {
        try (Engine engine = engineWithAllPasses()) {
            engine.update();
            log.clear();
            engine.update();
            engine.render();

            assertEquals(List.of(
                    "update hud", "update mirror", "update shadow", "update terrain", "update decals",
                    "shadow shadow", "reflection mirror", "main terrain", "main decals", "overlay hud"), log);
            Image image = engine.readImage();
            // lower left: hud (overlay) over decals over terrain; upper right: terrain alone
            assertEquals("255,0,0", rgb(image, SIZE / 4, SIZE * 3 / 4));
            assertEquals("0,255,0", rgb(image, SIZE * 3 / 4, SIZE / 4));
        }
        assertEquals(List.of("close decals", "close terrain", "close shadow", "close mirror", "close hud"),
                log.subList(log.size() - 5, log.size()));
    }

    @Test
    void aPreparingSystemRunsOnlyInPassesSomeoneDraws() {
        List<String> prepared = new ArrayList<>();
        EngineSystem preparer = new EngineSystem() {
            @Override
            public SystemSpec spec() {
                return SystemSpec.named("culling").prepares(Pass.SHADOW, Pass.MAIN);
            }

            @Override
            public void render(Pass pass, RenderContext context) {
                prepared.add(pass.label());
                log.add(pass.label() + " culling");
            }
        };
        Drawing after = new Drawing(SystemSpec.named("ground").after("culling").draws(Pass.MAIN),
                log, calls, GlTestSupport::fullScreenTriangle, 0, 1, 0);
        try (Engine engine = GlTestSupport.engine(GL.context(), SIZE, SIZE, after, preparer)) {
            engine.update();
            log.clear();
            engine.render();
        }
        assertEquals(List.of("main"), prepared, "no system draws in SHADOW, so that pass does not run");
        assertEquals(List.of("main culling", "main ground"), log.subList(0, 2));
    }

    @Test
    void eachPassGetsItsCamera() {
        try (Engine engine = engineWithAllPasses()) {
            engine.update();
            engine.render();

            Map<Pass, ViewCamera> byPass = new java.util.EnumMap<>(Pass.class);
            calls.forEach(c -> byPass.merge(c.pass(), c.camera(), (a, b) -> {
                assertSame(a, b, "two systems in " + c.pass() + " got different cameras");
                return a;
            }));
            assertSame(SUN_CAMERA, byPass.get(Pass.SHADOW));
            ViewCamera main = byPass.get(Pass.MAIN);
            assertNotSame(SUN_CAMERA, main);
            assertEquals(new Vector3f(10, 20, 30), main.position());
            ViewCamera reflection = byPass.get(Pass.REFLECTION);
            assertEquals(new Vector3f(10, -20, 30), reflection.position());
            assertTrue(reflection.mirrored() && !main.mirrored());
            assertSame(main, byPass.get(Pass.OVERLAY));
            Map<Pass, Framebuffer> targets = new java.util.EnumMap<>(Pass.class);
            calls.forEach(c -> targets.put(c.pass(), c.target()));
            assertSame(shadow.target, targets.get(Pass.SHADOW));
            assertSame(mirror.target, targets.get(Pass.REFLECTION));
            assertSame(targets.get(Pass.MAIN), targets.get(Pass.OVERLAY));
            assertEquals(SIZE, targets.get(Pass.MAIN).width());
        }
    }

    @Test
    void anOwnerIsGivenTheCameraMainDrawsWithMadeAnewEachFrame() {
        try (Engine engine = engineWithAllPasses()) {
            engine.update();
            engine.render();
            engine.render();
            List<ViewCamera> main = calls.stream().filter(c -> c.pass() == Pass.MAIN && c.system().equals("terrain"))
                    .map(Call::camera).toList();
            assertEquals(2, main.size());
            assertEquals(2, mirror.viewers.size());
            assertSame(main.get(0), mirror.viewers.get(0), "the reflection's viewer is MAIN's camera of that frame");
            assertSame(main.get(1), mirror.viewers.get(1));
            assertNotSame(main.get(0), main.get(1), "each frame makes its own viewer camera");
        }
    }

    /** A {@link Drawing} that logs its {@link EngineSystem#beginPass} calls. */
    static class Beginning extends Drawing {
        Beginning(SystemSpec spec, List<String> log, List<Call> calls, Function<GlContext, Mesh> meshFactory,
                  float... color) {
            super(spec, log, calls, meshFactory, color);
        }

        @Override
        public void beginPass(Pass pass, RenderContext context) {
            log.add("begin " + pass.label() + " " + spec.name());
        }
    }

    @Test
    void everyWorkingSystemBeginsThePassBeforeTheFirstDraws() {
        Beginning ground = new Beginning(SystemSpec.named("ground").draws(Pass.MAIN), log, calls,
                GlTestSupport::quarterQuad, 1, 1, 0);
        // drawn after the ground, but the state it sets for the pass holds for the ground's drawing too, as the
        // water's stencil rule holds for the terrain's: here, nothing drawn in MAIN writes red
        Beginning filter = new Beginning(SystemSpec.named("filter").after("ground").draws(Pass.MAIN), log, calls,
                GlTestSupport::quarterQuad, 1, 1, 1) {
            @Override
            public void beginPass(Pass pass, RenderContext context) {
                super.beginPass(pass, context);
                glColorMask(false, true, true, true);
            }

            @Override
            public void render(Pass pass, RenderContext context) {
                log.add(pass.label() + " filter");
                glColorMask(true, true, true, true);
            }
        };
        Beginning idle = new Beginning(SystemSpec.named("idle").draws(Pass.MAIN), log, calls,
                GlTestSupport::quarterQuad, 1, 0, 0);
        Beginning label = new Beginning(SystemSpec.named("label").draws(Pass.OVERLAY), log, calls,
                GlTestSupport::quarterQuad, 1, 1, 1);
        try (Engine engine = GlTestSupport.engine(GL.context(), SIZE, SIZE, filter, label, idle, ground)) {
            engine.setEnabled("idle", false);
            engine.update();
            log.clear();
            engine.render();
            assertEquals(List.of("begin main ground", "begin main filter", "main ground", "main filter",
                    "begin overlay label", "overlay label"), log, "switched off, idle neither begins nor draws");
            engine.setEnabled("label", false);
            engine.render();
            Image image = engine.readImage();
            assertEquals("0,255,0", rgb(image, SIZE / 4, SIZE * 3 / 4), "the ground's yellow without its red");
            assertEquals("0,0,0", rgb(image, SIZE * 3 / 4, SIZE / 4), "the clear colour where nothing was drawn");
        }
    }

    @Test
    void aPassIsSkippedWhileItsOwnerGivesNoView() {
        try (Engine engine = engineWithAllPasses()) {
            mirror.skip = true;
            engine.update();
            log.clear();
            engine.render();
            assertEquals(List.of("shadow shadow", "main terrain", "main decals", "overlay hud"), log);
        }
    }

    @Test
    void aPassRunsOncePerViewOfItsOwnerTimedApart() {
        try (Engine engine = engineWithAllPasses()) {
            shadow.views = 3;
            engine.update();
            log.clear();
            engine.render();
            assertEquals(List.of("shadow shadow", "shadow shadow", "shadow shadow", "reflection mirror"),
                    log.subList(0, 4));
            List<Float> heights = calls.stream().filter(c -> c.pass() == Pass.SHADOW)
                    .map(c -> c.camera().position().y()).toList();
            assertEquals(List.of(500f, 501f, 502f), heights, "the views in the owner's order");
            List<Map<String, Double>> spans = new ArrayList<>();
            engine.collectFrames(true, frame -> spans.add(frame.passGpuMs()));
            assertEquals(1, spans.size());
            assertTrue(spans.get(0).keySet().containsAll(List.of("shadow0.shadow", "shadow1.shadow",
                    "shadow2.shadow", "reflection.mirror", "main.terrain")), spans.get(0).keySet().toString());
        }
    }

    @Test
    void anUpdateThatWorksOnTheGpuIsTimedAsItsOwnSpanSummedOverTheFramesSteps() {
        Drawing simulated = new Drawing(SystemSpec.named("snow").updatesOnGpu().draws(Pass.MAIN), log, calls,
                GlTestSupport::fullScreenTriangle, 1, 1, 1);
        Drawing plain = new Drawing(SystemSpec.named("ground").draws(Pass.MAIN), log, calls,
                GlTestSupport::fullScreenTriangle, 0, 1, 0);
        try (Engine engine = GlTestSupport.engine(GL.context(), SIZE, SIZE, simulated, plain)) {
            engine.update();
            engine.update();
            engine.render();
            List<Map<String, Double>> spans = new ArrayList<>();
            engine.collectFrames(true, frame -> spans.add(frame.passGpuMs()));
            assertEquals(1, spans.size());
            assertTrue(spans.get(0).containsKey("update.snow"), spans.get(0).keySet().toString());
            assertFalse(spans.get(0).containsKey("update.ground"), "a CPU-only update has no GPU span");
            assertEquals(2, simulated.updates);
        }
    }

    @Test
    void aPassHasAtMostOneOwnerAndTheViewersPassesNone() {
        Owner second = new Owner(SystemSpec.named("second-mirror").draws(Pass.REFLECTION), Pass.REFLECTION,
                viewer -> viewer, log, calls, GlTestSupport::fullScreenTriangle, 1, 1, 1);
        SystemOrderException twice = assertThrows(SystemOrderException.class,
                () -> GlTestSupport.engine(GL.context(), SIZE, SIZE, mirror, second).close());
        assertTrue(twice.getMessage().contains("'mirror' and 'second-mirror' both own the reflection pass"),
                twice.getMessage());
        Owner main = new Owner(SystemSpec.named("thief").draws(Pass.MAIN), Pass.MAIN, viewer -> viewer, log, calls,
                GlTestSupport::fullScreenTriangle, 1, 1, 1);
        assertThrows(SystemOrderException.class, () -> GlTestSupport.engine(GL.context(), SIZE, SIZE, main).close());
        assertEquals(0, GL.context().objects().live());
    }

    @Test
    void frameRecordsCarryGpuTimesCountsCountersAndSystemTimes() {
        List<FrameRecord> records = new ArrayList<>();
        try (Engine engine = engineWithAllPasses()) {
            for (int i = 0; i < 3; i++) {
                engine.update();
                engine.render();
            }
            engine.collectFrames(true, records::add);
            engine.collectFrames(true, r -> records.add(null));
        }

        assertEquals(3, records.size(), "one record per frame, each handed over once");
        long triangles = 2 + 1 + 1 + 2 + 2; // shadow quad, mirror and terrain triangles, decals and hud quads
        for (int i = 0; i < records.size(); i++) {
            FrameRecord r = records.get(i);
            assertEquals(i, r.frame());
            assertEquals(List.of("shadow.shadow", "reflection.mirror", "main.terrain", "main.decals", "overlay.hud"),
                    List.copyOf(r.passGpuMs().keySet()), "one span per system in each pass, labelled pass.system");
            r.passGpuMs().forEach((pass, ms) -> assertTrue(ms >= 0 && Double.isFinite(ms), pass + ": " + ms));
            assertEquals(triangles, r.triangles());
            assertEquals(5, r.drawCalls());
            assertEquals(Map.of("shadow.casters", 3.0, "decals.drawn", 1.0), r.counters());
            assertEquals(List.of("hud", "mirror", "shadow", "terrain", "decals"), List.copyOf(r.systemCpuMs().keySet()));
            r.systemCpuMs().forEach((system, ms) -> assertTrue(ms >= 0, system + ": " + ms));
            assertTrue(r.cpuMs() > 0);
        }
        assertTrue(records.get(2).simTime() > records.get(0).simTime());
    }

    @Test
    void disabledSystemIsSkippedButNotClosed() {
        List<FrameRecord> records = new ArrayList<>();
        try (Engine engine = engineWithAllPasses()) {
            engine.setEnabled("hud", false);
            engine.setEnabled("mirror", false);
            engine.update();
            engine.render();

            assertFalse(log.stream().anyMatch(l -> l.endsWith(" hud") || l.endsWith(" mirror")), log.toString());
            assertFalse(hud.closed || mirror.closed);
            assertFalse(engine.isEnabled("hud"));
            assertEquals("off", engine.settings().text("system.hud"), "the switch lives in the settings");
            Image image = engine.readImage();
            assertEquals("0,0,255", rgb(image, SIZE / 4, SIZE * 3 / 4), "decals show without the hud");
            engine.collectFrames(true, records::add);
            FrameRecord r = records.get(0);
            assertEquals(List.of("shadow.shadow", "main.terrain", "main.decals"), List.copyOf(r.passGpuMs().keySet()));
            assertEquals(2 + 1 + 2, r.triangles());
            assertEquals(3, r.drawCalls());
            assertFalse(r.systemCpuMs().containsKey("hud"));

            // on again, through the setting (as --set, a settings file or the panel does): drawn again, with the
            // resources it kept
            engine.settings().set("system.hud", "on");
            log.clear();
            engine.update();
            engine.render();
            assertTrue(log.contains("overlay hud"), log.toString());
            assertEquals(1, hud.inits);
            assertEquals("255,0,0", rgb(engine.readImage(), SIZE / 4, SIZE * 3 / 4));
            assertThrows(IllegalArgumentException.class, () -> engine.setEnabled("huud", false));
        }
        assertTrue(hud.closed && mirror.closed, "disabled systems are closed with the engine");
    }

    /** Counts updates; draws nothing. */
    static final class Counting implements EngineSystem {
        int updates;

        @Override
        public SystemSpec spec() {
            return SystemSpec.named("counting");
        }

        @Override
        public void update(World world, double step) {
            updates++;
        }
    }

    /** Updates run by one advance call. */
    private static int stepsOf(Engine engine, Counting counting, double realSeconds) {
        int before = counting.updates;
        engine.advance(realSeconds);
        return counting.updates - before;
    }

    @Test
    void advanceRunsWholeFixedStepsAndCarriesTheRest() {
        Counting counting = new Counting();
        try (Engine engine = GlTestSupport.engine(GL.context(), SIZE, SIZE, counting)) {
            engine.settings().set("engine.step", "0.01");
            engine.settings().set("engine.max-steps", "8");

            assertEquals(3, stepsOf(engine, counting, 0.03));
            assertEquals(6, stepsOf(engine, counting, 0.06));
            assertEquals(0, stepsOf(engine, counting, 0.005));
            assertEquals(1, stepsOf(engine, counting, 0.005), "two halves make a step");
            assertEquals(0, stepsOf(engine, counting, 0.0049));
            assertEquals(2, stepsOf(engine, counting, 0.0151), "0.0049 s carried + 0.0151 s = 2 steps");
            // doubles: twelve sums of 0.01, off by a few ε only
            assertEquals(12 * 0.01, engine.simTime(), 1e-9, "simulation time is whole steps");
        }
    }

    @Test
    void advanceAtTheDefaultStepRunsWholeSteps() {
        Counting counting = new Counting();
        try (Engine engine = GlTestSupport.engine(GL.context(), SIZE, SIZE, counting)) {
            double step = engine.settings().get(EngineSettings.class).step();
            for (int n = 1; n <= engine.settings().get(EngineSettings.class).maxSteps(); n++) {
                assertEquals(n, stepsOf(engine, counting, n * step), "advance(" + n + " steps)");
            }
        }
    }

    @Test
    void advanceIsCappedByMaxStepsAndDropsTheBacklog() {
        Counting counting = new Counting();
        try (Engine engine = GlTestSupport.engine(GL.context(), SIZE, SIZE, counting)) {
            engine.settings().set("engine.step", "0.01");
            engine.settings().set("engine.max-steps", "4");

            assertEquals(4, stepsOf(engine, counting, 1.0));
            assertEquals(0, stepsOf(engine, counting, 0.005), "the 0.96 s not simulated is dropped, not carried");
        }
    }

    @Test
    void failingInitClosesWhatWasAlreadyCreated() {
        List<String> events = new ArrayList<>();
        EngineSystem first = new EngineSystem() {
            private GpuBuffer buffer;

            @Override
            public SystemSpec spec() {
                return SystemSpec.named("first");
            }

            @Override
            public void init(EngineContext context) {
                buffer = new GpuBuffer(context.gl(), GL_ARRAY_BUFFER);
                buffer.allocate(1024, GL_STATIC_DRAW);
                events.add("init first");
            }

            @Override
            public void close() {
                buffer.close();
                events.add("close first");
            }
        };
        EngineSystem second = new EngineSystem() {
            @Override
            public SystemSpec spec() {
                return SystemSpec.named("second").after("first");
            }

            @Override
            public void init(EngineContext context) {
                throw new IllegalStateException("no terrain data in assets/");
            }
        };

        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> GlTestSupport.engine(GL.context(), SIZE, SIZE, second, first));

        assertEquals("no terrain data in assets/", e.getMessage());
        assertEquals(List.of("init first", "close first"), events);
        assertEquals(0, GL.context().objects().live(), "the engine's own target and uniform buffer are closed too: " + GL.context().objects());
    }
}

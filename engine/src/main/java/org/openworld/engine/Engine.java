package org.openworld.engine;

import static org.lwjgl.opengl.GL11C.*;
import static org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.glBindFramebuffer;

import java.nio.FloatBuffer;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.joml.Matrix4f;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.bench.FrameRecord;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.Owned;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.PassOwner;
import org.openworld.engine.core.PassView;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemOrder;
import org.openworld.engine.core.SystemOrderException;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.core.World;
import org.openworld.engine.environment.Exposure;
import org.openworld.engine.environment.SkyMaps;
import org.openworld.engine.environment.SunShadow;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.gl.CubeMapTexture;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.FrameThrottle;
import org.openworld.engine.gl.FrameUniforms;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.GpuTimers;
import org.openworld.engine.gl.Image;
import org.openworld.engine.gl.ShaderLibrary;
import org.openworld.engine.gl.ShaderSources;
import org.openworld.engine.gl.SharedBlock;
import org.openworld.engine.gl.SharedTexture;
import org.openworld.engine.gl.Texture2D;
import org.openworld.engine.gl.Texture3D;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Owns the world and the systems and runs the frame (DESIGN.md, "Core"):
 * <ol>
 *   <li>fixed-step {@code update}: every enabled system, in resolved order, advances by exactly one step;</li>
 *   <li>render passes SHADOW → REFLECTION → MAIN → OVERLAY: for each pass that some system draws in (and, for SHADOW
 *       and REFLECTION, whose {@link PassOwner} gives a view this frame), the frame uniform block is written with
 *       that pass's camera, its target is bound and cleared, and the systems draw in resolved order;</li>
 *   <li>the picture is in the scene target, to be read back (headless) or shown (window).</li>
 * </ol>
 * Each system's CPU time and each pass's GPU time (timer queries) are measured every frame and come out as
 * {@link FrameRecord}s once the GPU has finished them.
 */
public final class Engine implements AutoCloseable {

    private final GlContext gl;
    private final World world = new World();
    private final Settings settings;
    private final ShaderLibrary shaders;
    private final SystemOrder order;
    /** The systems drawing in or preparing each pass, in resolved order; fixed at start-up. */
    private final Map<Pass, List<EngineSystem>> drawingIn = new EnumMap<>(Pass.class);
    /** The system owning SHADOW or REFLECTION, if any. */
    private final Map<Pass, EngineSystem> owners = new EnumMap<>(Pass.class);
    private final DrawStats stats = new DrawStats();
    private final Counters counters = new Counters();
    /** The systems whose init has begun, in order, with what each has handed to {@link EngineContext#own}. */
    private final Map<EngineSystem, Owned> initialised = new LinkedHashMap<>();
    private final Deque<FrameRecord> awaitingGpu = new ArrayDeque<>();
    private final Map<String, Double> systemNanos = new LinkedHashMap<>();
    private Framebuffer scene;
    private FrameUniforms frameUniforms;
    private GpuTimers timers;
    private FrameThrottle throttle;
    private SkyMaps neutralSky;
    private SunShadow noShadow;
    private double simTime;
    private long lastFrameEnd;
    private double unsimulated;
    private long frame;

    /**
     * Resolves the system order and initialises every system (on this, the GL thread).
     *
     * @param gl       the current GL context
     * @param shaders  where shader files come from
     * @param settings every setting, already with the user's {@code --set} values
     * @param systems  the systems, in any order: the engine orders them from their declarations
     * @param width    scene target width, pixels
     * @param height   scene target height, pixels
     */
    public Engine(GlContext gl, ShaderSources shaders, Settings settings, List<EngineSystem> systems,
                  int width, int height) {
        this.gl = gl;
        this.shaders = new ShaderLibrary(gl, shaders);
        this.settings = settings;
        this.order = SystemOrder.resolve(systems);
        for (EngineSystem system : order.systems()) {
            if (!settings.hasSystem(system.spec().name())) {
                throw new IllegalArgumentException("the settings have no switch for system '" + system.spec().name()
                        + "': make them with Engine.settingsFor(systems)");
            }
        }
        for (Pass pass : Pass.values()) {
            drawingIn.put(pass, order.systems().stream()
                    .filter(s -> s.spec().passes().contains(pass) || s.spec().prepared().contains(pass)).toList());
        }
        for (EngineSystem system : order.systems()) {
            if (system instanceof PassOwner owner) {
                Pass pass = owner.ownedPass();
                if (pass == Pass.MAIN || pass == Pass.OVERLAY) {
                    throw new SystemOrderException("system '" + system.spec().name() + "' claims the " + pass.label()
                            + " pass, which the engine draws with the viewer's camera into the scene");
                }
                EngineSystem other = owners.put(pass, system);
                if (other != null) {
                    throw new SystemOrderException("systems '" + other.spec().name() + "' and '"
                            + system.spec().name() + "' both own the " + pass.label() + " pass");
                }
            }
        }
        world.setResource(settings);
        world.setResource(counters);
        world.setResource(new TimeOfDay(10.0, 0.0));
        world.setResource(new Camera());
        try {
            scene = Framebuffer.scene(gl, width, height);
            frameUniforms = new FrameUniforms(gl);
            timers = new GpuTimers(gl);
            throttle = new FrameThrottle(gl);
            neutralSky = neutralSky(gl);
            noShadow = SunShadow.none(gl);
            for (EngineSystem system : order.systems()) {
                // Added first, so a system whose init fails half-way is closed with the others.
                Owned owned = new Owned();
                initialised.put(system, owned);
                system.init(new EngineContext(gl, world, this.shaders, settings, owned));
            }
        } catch (RuntimeException e) {
            close();
            throw e;
        }
    }

    /**
     * Settings at their defaults for the engine's own group, every group these systems declare, and an on/off switch
     * per system ({@code system.name}), on unless its spec says
     * {@link org.openworld.engine.core.SystemSpec#offByDefault() offByDefault}.
     */
    public static Settings settingsFor(List<? extends EngineSystem> systems) {
        List<SettingsGroup<?>> groups = new ArrayList<>(List.of(EngineSettings.GROUP));
        Map<String, Boolean> switches = new LinkedHashMap<>();
        systems.forEach(s -> {
            groups.addAll(s.settings());
            switches.put(s.spec().name(), !s.spec().isOffByDefault());
        });
        return new Settings(groups, switches);
    }

    public World world() {
        return world;
    }

    public Settings settings() {
        return settings;
    }

    public SystemOrder order() {
        return order;
    }

    public GlContext gl() {
        return gl;
    }

    public ShaderLibrary shaders() {
        return shaders;
    }

    /** Simulation time, seconds: the number of updates times the step. */
    public double simTime() {
        return simTime;
    }

    /** Frames rendered so far. */
    public long frame() {
        return frame;
    }

    public int width() {
        return scene.width();
    }

    public int height() {
        return scene.height();
    }

    /**
     * Switches a system's update and render off or on; its GPU resources stay (STYLE.md 6). The same as setting
     * {@code system.name}, which is where the switch lives.
     */
    public void setEnabled(String system, boolean enabled) {
        if (!settings.hasSystem(system)) {
            throw new IllegalArgumentException("no system named '" + system + "'");
        }
        settings.set(Settings.SYSTEM_PREFIX + system, enabled ? "on" : "off");
    }

    public boolean isEnabled(String system) {
        return settings.systemEnabled(system);
    }

    /** Advances the simulation by exactly one fixed step. */
    public void update() {
        double step = settings.get(EngineSettings.class).step();
        for (EngineSystem system : order.systems()) {
            if (isEnabled(system.spec().name())) {
                long t0 = System.nanoTime();
                boolean timed = system.spec().isUpdatedOnGpu();
                if (timed) {
                    timers.begin("update." + system.spec().name());
                }
                system.update(world, step);
                if (timed) {
                    timers.end();
                }
                systemNanos.merge(system.spec().name(), (double) (System.nanoTime() - t0), Double::sum);
            }
        }
        world.setResource(world.resource(TimeOfDay.class).advance(step));
        simTime += step;
    }

    /**
     * Slack when comparing the time not yet simulated with the step, seconds: far below any step, far above the
     * rounding error of the sums, so 0.03 s at a 0.01 s step runs 3 steps, not 2 (0.03 − 0.01 − 0.01 &lt; 0.01 in
     * doubles).
     */
    private static final double STEP_SLACK = 1e-9;

    /**
     * Runs as many fixed steps as fit in {@code realSeconds} of wall-clock time plus what was left over, at most
     * {@link EngineSettings#maxSteps()} (the window's loop; benchmarks call {@link #update()} once per frame).
     */
    public void advance(double realSeconds) {
        EngineSettings s = settings.get(EngineSettings.class);
        unsimulated += realSeconds;
        int steps = 0;
        while (unsimulated >= s.step() - STEP_SLACK && steps < s.maxSteps()) {
            update();
            unsimulated -= s.step();
            steps++;
        }
        if (steps == s.maxSteps()) {
            unsimulated = 0;
        }
    }

    /** Renders every pass into the scene target and records the frame's statistics. */
    public void render() {
        long frameStart = System.nanoTime();
        stats.reset();
        PassView viewer = new PassView(world.resource(Camera.class).view((float) scene.width() / scene.height()), scene);
        boolean shadowDrawn = false;
        for (Pass pass : Pass.values()) {
            List<EngineSystem> drawing = drawingIn.get(pass);
            if (drawing.stream().noneMatch(s -> s.spec().passes().contains(pass) && isEnabled(s.spec().name()))) {
                continue;
            }
            List<PassView> views = views(pass, viewer);
            for (int v = 0; v < views.size(); v++) {
                PassView view = views.get(v);
                // 1. the pass's camera and the world's light into the frame block; the shared textures to their units
                frameUniforms.write(frameValues(view, viewer));
                bindShared(shadowDrawn);
                // 2. the target, bound and (but for OVERLAY, which draws over the picture) cleared
                view.target().bind();
                glFrontFace(view.camera().mirrored() ? GL_CW : GL_CCW);
                if (pass != Pass.OVERLAY) {
                    clear(pass);
                }
                // 3. the systems draw, each timed on the GPU as one span labelled pass.system, or passN.system
                //    for the N-th of several views (shadow0.terrain, shadow1.terrain, ... one per cascade)
                String label = pass.label() + (views.size() > 1 ? String.valueOf(v) : "") + ".";
                RenderContext context = new RenderContext(world, view.camera(), stats, view.target());
                for (EngineSystem system : drawing) {
                    if (!isEnabled(system.spec().name())) {
                        continue;
                    }
                    long t0 = System.nanoTime();
                    timers.begin(label + system.spec().name());
                    system.render(pass, context);
                    timers.end();
                    systemNanos.merge(system.spec().name(), (double) (System.nanoTime() - t0), Double::sum);
                }
            }
            shadowDrawn |= pass == Pass.SHADOW && !views.isEmpty();
        }
        glFrontFace(GL_CCW);
        glDisable(GL_STENCIL_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        timers.endFrame(frame);
        double cpuMs = (System.nanoTime() - frameStart) / 1e6;
        // 4. at most two frames in flight, as with a swap chain, so timings measure frames and not a queue
        throttle.endFrame();
        long frameEnd = System.nanoTime();
        double wallMs = (frameEnd - (lastFrameEnd != 0 ? lastFrameEnd : frameStart)) / 1e6;
        lastFrameEnd = frameEnd;
        awaitingGpu.add(cpuRecord(wallMs, cpuMs));
        systemNanos.clear();
        counters.clear();
        frame++;
    }

    /** MAIN and OVERLAY: the viewer into the scene; SHADOW and REFLECTION: their owner's views, none to skip. */
    private List<PassView> views(Pass pass, PassView viewer) {
        if (pass == Pass.MAIN || pass == Pass.OVERLAY) {
            return List.of(viewer);
        }
        EngineSystem owner = owners.get(pass);
        if (owner == null || !isEnabled(owner.spec().name())) {
            return List.of();
        }
        return ((PassOwner) owner).passViews(world, viewer);
    }

    /**
     * Clears a pass's target. MAIN starts black, with the stencil at 0xFF everywhere and every fragment that passes
     * the depth test writing 0: the first step of the paper's water (section 3.3), "stencil clear value 0xFF, the
     * terrain writes 0", kept as the engine's rule so no drawing system need know of it. A system that marks its
     * pixels otherwise (the water writes 0xFF) sets its own stencil state and puts this one back. An owned pass
     * (shadow map, reflection) starts with alpha 0, so a reader can tell where nothing was drawn.
     */
    private static void clear(Pass pass) {
        boolean main = pass == Pass.MAIN;
        glClearColor(0, 0, 0, main ? 1 : 0);
        glClearStencil(0xFF);
        glDepthMask(true);
        glStencilMask(0xFF);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        if (main) {
            glEnable(GL_STENCIL_TEST);
            glStencilFunc(GL_ALWAYS, 0, 0xFF);
            glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        } else {
            glDisable(GL_STENCIL_TEST);
        }
    }

    /** The block for one view of a pass; {@code viewer} is the MAIN camera's, given to every pass as the viewer. */
    private FrameUniforms.Values frameValues(PassView view, PassView viewer) {
        ViewCamera camera = view.camera();
        Sun sun = world.findResource(Sun.class).orElse(Sun.NOON);
        Exposure exposure = world.findResource(Exposure.class).orElse(Exposure.NONE);
        return new FrameUniforms.Values(new Matrix4f(camera.view()), new Matrix4f(camera.projection()),
                camera.position(), camera.near(), camera.far(), sun.direction(), sun.color(), sun.ambient(),
                exposure.scale(), simTime, world.resource(TimeOfDay.class).hours(), frame, view.target().width(),
                view.target().height(), viewer.camera().position());
    }

    /**
     * Binds the shared textures and blocks: the sky's, or neutral stand-ins when no system models the sky; the sun's
     * shadow once this frame's maps are drawn, else none (no system casts shadows, it is switched off or the sun is
     * down; and a map being drawn must not be bound for reading).
     */
    private void bindShared(boolean shadowDrawn) {
        SkyMaps maps = world.findResource(SkyMaps.class).orElse(neutralSky);
        maps.aerialPerspective().bind(SharedTexture.AERIAL_PERSPECTIVE.unit());
        maps.environment().bind(SharedTexture.ENVIRONMENT.unit());
        SunShadow shadow = shadowDrawn ? world.findResource(SunShadow.class).orElse(noShadow) : noShadow;
        shadow.map().bind(SharedTexture.SHADOW_MAP.unit());
        shadow.block().bindBase(SharedBlock.SHADOW.binding());
    }

    /** No air (nothing scattered in, everything transmitted) and a uniform sky as bright as the noon sun's ambient. */
    private static SkyMaps neutralSky(GlContext gl) {
        FloatBuffer clearAir = MemoryUtil.memAllocFloat(4).put(0).put(0).put(0).put(1).flip();
        try {
            Texture3D air = Texture3D.of(gl, 1, 1, 1, Texture2D.Format.RGBA16F, Texture3D.Sampling3D.LINEAR_CLAMP,
                    clearAir);
            return new SkyMaps(air, CubeMapTexture.fromDirections(gl, 1, d -> Sun.NOON.ambient()));
        } finally {
            MemoryUtil.memFree(clearAir);
        }
    }

    private FrameRecord cpuRecord(double wallMs, double cpuMs) {
        Map<String, Double> systemMs = new LinkedHashMap<>();
        for (EngineSystem s : order.systems()) {
            Double nanos = systemNanos.get(s.spec().name());
            if (nanos != null) {
                systemMs.put(s.spec().name(), nanos / 1e6);
            }
        }
        return new FrameRecord((int) frame, simTime, wallMs, cpuMs, systemMs, Map.of(), stats.triangles(), stats.drawCalls(),
                counters.snapshot());
    }

    /**
     * Hands over the records of frames whose GPU timings have arrived, oldest first.
     *
     * @param wait true to wait for the GPU to finish every frame rendered so far
     */
    public void collectFrames(boolean wait, Consumer<FrameRecord> sink) {
        timers.collect(wait, (frameIndex, gpuMs) -> {
            FrameRecord cpu = awaitingGpu.pop();
            sink.accept(new FrameRecord(cpu.frame(), cpu.simTime(), cpu.wallMs(), cpu.cpuMs(), cpu.systemCpuMs(), gpuMs,
                    cpu.triangles(), cpu.drawCalls(), cpu.counters()));
        });
    }

    /** Reads the scene target back (waits for the GPU). */
    public Image readImage() {
        return scene.read();
    }

    /**
     * Runs drawing that goes over the finished picture, into the scene target (the window's settings panel and HUD),
     * so that what is shown and what is read back are one picture.
     */
    public void drawOver(Runnable drawing) {
        scene.bind();
        drawing.run();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    /** Shows the scene target in the window, scaled to its framebuffer. */
    public void present(int screenWidth, int screenHeight) {
        scene.blitToScreen(screenWidth, screenHeight);
    }

    /** Re-creates the scene target at a new size (a resized window); 0×0 (minimised) is ignored. */
    public void resize(int width, int height) {
        if (width <= 0 || height <= 0 || (width == scene.width() && height == scene.height())) {
            return;
        }
        scene.close();
        scene = Framebuffer.scene(gl, width, height);
    }

    /**
     * Closes every system in reverse order (its own {@code close()}, then what it owned, newest first), then the
     * engine's own GL objects; a failing close does not stop the others, and every failure is reported at the end.
     */
    @Override
    public void close() {
        Owned all = new Owned();
        initialised.forEach((system, owned) -> {
            all.own(owned);
            all.own(system);
        });
        initialised.clear();
        try {
            all.close();
        } finally {
            closeEngineObjects();
        }
    }

    private void closeEngineObjects() {
        if (neutralSky != null) {
            neutralSky.environment().close();
            neutralSky.aerialPerspective().close();
        }
        if (noShadow != null) {
            noShadow.close();
        }
        if (throttle != null) {
            throttle.close();
        }
        if (timers != null) {
            timers.close();
        }
        if (frameUniforms != null) {
            frameUniforms.close();
        }
        if (scene != null) {
            scene.close();
        }
    }
}

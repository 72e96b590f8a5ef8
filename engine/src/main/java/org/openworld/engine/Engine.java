package org.openworld.engine;

import static org.lwjgl.opengl.GL11C.*;
import static org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.glBindFramebuffer;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;
import org.openworld.engine.antialias.AntialiasSettings;
import org.openworld.engine.antialias.Antialiasing;
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
import org.openworld.engine.core.World;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Image;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.ShaderLibrary;
import org.openworld.engine.gl.ShaderSources;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Owns the world and the systems and runs the frame (docs/design.md, "Core"):
 * <ol>
 *   <li>fixed-step {@code update}: every enabled system, in resolved order, advances by exactly one step;</li>
 *   <li>render passes SHADOW → REFLECTION → MAIN → OVERLAY: for each pass that some system draws in (and, for SHADOW
 *       and REFLECTION, whose {@link PassOwner} gives a view this frame), the frame uniform block is written with
 *       that pass's camera, its target is bound and cleared, each system working in it sets up the pass
 *       ({@link EngineSystem#beginPass}), and the systems draw in resolved order;</li>
 *   <li>with {@code antialias.method} on, the scene target anti-aliased ({@link Antialiasing});</li>
 *   <li>below {@code engine.render-scale} 1, the scene target, drawn smaller, is stretched over the full-size
 *       picture; at 2, drawn larger, it is halved, each pixel the mean of four ({@link ScaledScene});</li>
 *   <li>the picture is read back (headless) or shown (window).</li>
 * </ol>
 * Each system's CPU time and each pass's GPU time (timer queries) are measured every frame and come out as
 * {@link FrameRecord}s once the GPU has finished them. Three parts live in classes of their own: the simulation's
 * clock ({@link FixedStepClock}), the frame's timings ({@link FrameTiming}) and what every pass's shaders can read
 * without binding it (the frame block and the world's shared resources: {@link SharedBindings}).
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
    /**
     * The engine's own GL objects, labelled {@code engine.*}: the scene target and picture, the timers, the shared
     * bindings.
     */
    private final Owned owned = new Owned("engine");
    private final FixedStepClock clock = new FixedStepClock();
    private ScaledScene scene;
    private FrameTiming timing;
    private SharedBindings shared;
    private Antialiasing antialiasing;
    private long frame;

    /**
     * Resolves the system order and initialises every system (on this, the GL thread).
     *
     * @param gl       the current GL context
     * @param shaders  where shader files come from
     * @param settings every setting, already with the user's {@code --set} values
     * @param systems  the systems, in any order: the engine orders them from their declarations
     * @param width    picture width, pixels
     * @param height   picture height, pixels
     */
    public Engine(GlContext gl, ShaderSources shaders, Settings settings, List<EngineSystem> systems,
                  int width, int height) {
        this.gl = gl;
        this.shaders = new ShaderLibrary(gl, shaders, true, EngineSystem.shaderConstants(systems));
        this.settings = settings;
        this.order = SystemOrder.resolve(systems);
        for (EngineSystem system : order.systems()) {
            if (!settings.hasSystem(system.spec().name())) {
                throw new IllegalArgumentException("the settings have no switch for system '" + system.spec().name()
                        + "': make them with Engine.settingsFor(systems)");
            }
        }
        for (Pass pass : Pass.values()) {
            drawingIn.put(pass, order.drawOrder(pass));
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
            scene = new ScaledScene(gl, owned, width, height, renderScale(),
                    settings.get(AntialiasSettings.class).enabled());
            antialiasing = owned.own(new Antialiasing(gl, this.shaders));
            timing = new FrameTiming(gl, owned, order.systems());
            shared = new SharedBindings(gl, owned, world);
            for (EngineSystem system : order.systems()) {
                // Added first, so a system whose init fails half-way is closed with the others.
                Owned made = new Owned(system.spec().name());
                initialised.put(system, made);
                system.init(new EngineContext(gl, world, this.shaders, settings, made));
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
        List<SettingsGroup<?>> groups = new ArrayList<>(List.of(EngineSettings.GROUP, AntialiasSettings.GROUP));
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
        return clock.simTime();
    }

    /** Frames rendered so far. */
    public long frame() {
        return frame;
    }

    /** The picture's width: what is shown and read back, whatever the render scale. */
    public int width() {
        return scene.picture().width();
    }

    public int height() {
        return scene.picture().height();
    }

    private double renderScale() {
        return settings.get(EngineSettings.class).renderScale();
    }

    /**
     * Switches a system's update and render off or on; its GPU resources stay (CONTRIBUTING.md, "Lifecycle"). The same as setting
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

    /**
     * Profiles every frame from the first (docs/benchmarks.md, "Profiling"): the GPU is finished around each span
     * (each system in each pass, each update, each pass's clear as {@code pass.engine}) and the span's wall time is
     * recorded in place of its timer query, so the spans split the frame exactly on any driver, llvmpipe included,
     * at the price of a serialised, slower frame.
     *
     * @throws IllegalStateException after the first frame
     */
    public void profile() {
        timing.profile();
    }

    /** Advances the simulation by exactly one fixed step. */
    public void update() {
        double step = settings.get(EngineSettings.class).step();
        for (EngineSystem system : order.systems()) {
            String name = system.spec().name();
            if (isEnabled(name)) {
                timing.time(name, system.spec().isUpdatedOnGpu() || timing.profiling() ? "update." + name : null,
                        () -> system.update(world, step));
            }
        }
        world.setResource(world.resource(TimeOfDay.class).advance(step));
        clock.stepped(step);
    }

    /**
     * Runs as many fixed steps as fit in {@code realSeconds} of wall-clock time plus what was left over, at most
     * {@link EngineSettings#maxSteps()} ({@link FixedStepClock}; the window's loop, while benchmarks call
     * {@link #update()} once per frame).
     */
    public void advance(double realSeconds) {
        EngineSettings s = settings.get(EngineSettings.class);
        for (int steps = clock.stepsOwed(realSeconds, s.step(), s.maxSteps()); steps > 0; steps--) {
            update();
        }
    }

    /** Renders every pass into the scene target, then makes the picture from it, and records the frame's statistics. */
    public void render() {
        timing.beginFrame();
        stats.reset();
        AntialiasSettings antialias = settings.get(AntialiasSettings.class);
        scene.fit(width(), height(), renderScale(), antialias.enabled()); // either may have changed (the panel)
        var eye = world.resource(Camera.class).view((float) width() / height());
        PassView viewer = shared.viewer(world, antialiasing.viewer(eye, frame, scene.scene(), antialias), scene.scene());
        world.setResource(viewer); // for a pass drawn with the viewer in mind (shadow casters at the viewer's detail)
        shared.beginFrame(owners.values());
        for (Pass pass : Pass.values()) {
            List<EngineSystem> drawing = drawingIn.get(pass);
            if (drawing.stream().noneMatch(s -> s.spec().passes().contains(pass) && isEnabled(s.spec().name()))) {
                continue;
            }
            List<PassView> views = views(pass, viewer);
            for (int v = 0; v < views.size(); v++) {
                PassView view = views.get(v);
                // 1. the pass's camera and the world's light into the frame block; the shared textures to their units
                Set<Class<?>> bound = shared.bind(world, view, viewer, clock.simTime(), frame);
                // 2. the target, bound and (but for OVERLAY, which draws over the picture) cleared
                String label = pass.label() + (view.number() >= 0 ? String.valueOf(view.number()) : "") + ".";
                timing.timeEngine(label + "engine", () -> {
                    view.target().bind();
                    glDisable(GL_SCISSOR_TEST); // the whole target; a pass's owner may scissor it in beginPass
                    glFrontFace(view.camera().mirrored() ? GL_CW : GL_CCW);
                    if (pass != Pass.OVERLAY) {
                        clear(pass);
                    }
                });
                // 3. each system's state for the whole pass (EngineSystem.beginPass), before anyone draws
                RenderContext context = new RenderContext(world, view.camera(), stats, view.target(), bound);
                for (EngineSystem system : drawing) {
                    if (isEnabled(system.spec().name())) {
                        system.beginPass(pass, context);
                    }
                }
                // 4. the systems draw, each timed on the GPU as one span labelled pass.system, or passN.system
                //    for the view numbered N by its owner (shadow0.terrain, shadow1.terrain, ... one per cascade)
                for (EngineSystem system : drawing) {
                    if (!isEnabled(system.spec().name())) {
                        continue;
                    }
                    timing.time(system.spec().name(), label + system.spec().name(),
                            () -> system.render(pass, context));
                }
            }
            // the maps are ready once their owner has had its turn, even with no view: it may keep the last frame's
            shared.release(hasEnabledOwner(pass) ? owners.get(pass).spec().writes() : Set.of());
        }
        // a neutral state for whatever draws next (the window's panel): front faces wind CCW, no stencil nor scissor
        glFrontFace(GL_CCW);
        glDisable(GL_STENCIL_TEST);
        glDisable(GL_SCISSOR_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        // 5. the scene anti-aliased, then below scale 1 stretched over the picture: part of the frame, timed as such
        if (scene.antialiased()) {
            timing.timeEngine("antialias.engine", () -> antialiasing.draw(scene.scene(), scene.resolved(), stats));
        }
        if (scene.scaled()) {
            timing.timeEngine("upscale.engine", scene::upscale);
        }
        // 6. the frame's times queued for its GPU times; at most two frames in flight, as with a swap chain
        timing.endFrame(frame, clock.simTime(), stats, counters);
        counters.clear();
        frame++;
    }

    /** MAIN and OVERLAY: the viewer into the scene; SHADOW and REFLECTION: their owner's views, none to skip. */
    private List<PassView> views(Pass pass, PassView viewer) {
        if (pass == Pass.MAIN || pass == Pass.OVERLAY) {
            return List.of(viewer);
        }
        return hasEnabledOwner(pass) ? ((PassOwner) owners.get(pass)).passViews(world, viewer) : List.of();
    }

    private boolean hasEnabledOwner(Pass pass) {
        EngineSystem owner = owners.get(pass);
        return owner != null && isEnabled(owner.spec().name());
    }

    /**
     * Clears a pass's target: colour, depth and stencil (to 0). MAIN starts black; an owned pass (shadow map,
     * reflection) starts with alpha 0, so a reader can tell where nothing was drawn. Nothing else: a system that needs
     * a state for the whole pass (the water's stencil rule) sets it in its {@link EngineSystem#beginPass}.
     */
    private static void clear(Pass pass) {
        glClearColor(0, 0, 0, pass == Pass.MAIN ? 1 : 0);
        glClearStencil(0);
        glDepthMask(true);
        glStencilMask(0xFF);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    }

    /**
     * Hands over the records of frames whose GPU timings have arrived, oldest first.
     *
     * @param wait true to wait for the GPU to finish every frame rendered so far
     */
    public void collectFrames(boolean wait, Consumer<FrameRecord> sink) {
        timing.collect(wait, sink);
    }

    /** Reads the picture back (waits for the GPU). */
    public Image readImage() {
        return scene.picture().read();
    }

    /**
     * Runs drawing that goes over the finished picture (the window's settings panel and HUD), at the picture's full
     * size whatever the render scale, so that what is shown and what is read back are one picture.
     */
    public void drawOver(Runnable drawing) {
        scene.picture().bind();
        drawing.run();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    /** Shows the picture in the window, scaled to its framebuffer. */
    public void present(int screenWidth, int screenHeight) {
        scene.picture().blitToScreen(screenWidth, screenHeight);
    }

    /** Re-creates the scene target and picture at a new size (a resized window); 0×0 (minimised) is ignored. */
    public void resize(int width, int height) {
        scene.fit(width, height, renderScale(), settings.get(AntialiasSettings.class).enabled());
    }

    /**
     * Closes every system in reverse order (its own {@code close()}, then what it owned, newest first), then the
     * engine's own GL objects; a failing close does not stop the others, and every failure is reported at the end.
     */
    @Override
    public void close() {
        Owned all = new Owned();
        all.own(owned);
        initialised.forEach((system, made) -> {
            all.own(made);
            all.own(system);
        });
        initialised.clear();
        all.close();
    }
}

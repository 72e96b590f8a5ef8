package org.openworld.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE;
import static org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.environment.SkyMaps;
import org.openworld.engine.environment.SunShadow;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.GlDebug;
import org.openworld.engine.gl.GlObjects;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.Texture2D;
import org.openworld.engine.minimap.MinimapSystem;
import org.openworld.engine.particles.ParticleSystem;
import org.openworld.engine.shadow.ShadowSystem;
import org.openworld.engine.sky.SkySystem;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.TerrainSystem;
import org.openworld.engine.water.WaterSystem;

/**
 * Every engine system on real GL, owning through {@code context.own}: start-up and shutdown leave no GL object
 * behind (also after an init that fails half-way, and after targets are re-made while running), and what the
 * systems own carries labels named like their timer spans. What the terrain owns differs between its two worlds (the
 * tile's maps, or the unbounded world's clipmap and its workers), so the lifetimes are checked on both.
 */
@GlTest
class SystemsOwnershipTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final List<String> SMALL_WORLD = List.of("terrain.size=256", "lod.patch-vertices=33",
            "system.minimap=on", "system.particles=on", "particles.count=1000", "shadow.resolution=256");

    /** The engine's systems but the camera (which makes no GL objects), in the demo's order. */
    static List<EngineSystem> systems() {
        return List.of(new SkySystem(), new CullingSystem(), new TerrainSystem(line -> { }), new ShadowSystem(),
                new WaterSystem(), new MinimapSystem(), new ParticleSystem());
    }

    /** The small world on the given terrain. */
    static List<String> smallWorld(TerrainSettings.World world) {
        List<String> settings = new ArrayList<>(SMALL_WORLD);
        settings.add("terrain.world=" + world);
        return settings;
    }

    /** The engine, its camera 120 m over the ground (the two worlds' heights differ there). */
    private static Engine start(List<EngineSystem> systems, List<String> settings) {
        Engine engine = GlTestSupport.engine(GL.context(), 96, 64, settings, systems.toArray(EngineSystem[]::new));
        double ground = engine.world().resource(HeightField.class).heightAt(0, 300);
        engine.world().resource(Camera.class).setPose(new CameraPose(0, ground + 120, 300, 0, -10, 60));
        return engine;
    }

    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    void startUpRenderingAndShutdownLeaveNoGlObject(TerrainSettings.World world) {
        int live;
        try (Engine engine = start(systems(), smallWorld(world))) {
            engine.update();
            engine.render();
            engine.render();
            engine.collectFrames(true, frame -> { });
            live = GL.context().objects().live();
        }
        assertEquals(0, GL.context().objects().live(), "left alive: " + GL.context().objects());
        // a full engine makes dozens of GL objects (95 after SoakTest's first frame): 40 only says the systems made
        // theirs
        assertTrue(live > 40, "the systems made their objects: " + live);
    }

    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    void objectsRemadeWhileRunningAreClosedAsTheyAreReplaced(TerrainSettings.World world) {
        try (Engine engine = start(systems(), smallWorld(world))) {
            engine.update();
            engine.render();
            Map<GlObjects.Kind, Integer> before = resources();
            engine.settings().set("water.wind", "12");      // new ripples
            engine.settings().set("shadow.resolution", "512"); // new maps and layers
            engine.settings().set("particles.count", "2000"); // new state buffers
            engine.resize(80, 48);                              // new scene target, so new water targets
            engine.update();
            engine.render();
            engine.render();
            engine.collectFrames(true, frame -> { });
            assertEquals(before, resources(), "as many objects as before: " + GL.context().objects());
        }
    }

    /** Live objects of the kinds systems own (timer queries and fences come and go with the frames in flight). */
    private static Map<GlObjects.Kind, Integer> resources() {
        Map<GlObjects.Kind, Integer> live = new EnumMap<>(GlObjects.Kind.class);
        for (GlObjects.Kind kind : List.of(GlObjects.Kind.PROGRAM, GlObjects.Kind.BUFFER, GlObjects.Kind.VERTEX_ARRAY,
                GlObjects.Kind.TEXTURE, GlObjects.Kind.FRAMEBUFFER)) {
            live.put(kind, GL.context().objects().live(kind));
        }
        return live;
    }

    @Test
    void whatSystemsOwnIsLabelledSystemDotRole() {
        List<EngineSystem> systems = systems();
        try (Engine engine = start(systems, SMALL_WORLD)) {
            engine.render();
            GlDebug debug = GL.context().debug();
            SkyMaps sky = engine.world().resource(SkyMaps.class);
            SunShadow shadow = engine.world().resource(SunShadow.class);
            WaterSystem water = (WaterSystem) systems.get(4);
            assertEquals("sky.aerialPerspective", debug.labelOf(GL_TEXTURE, sky.aerialPerspective().id()));
            assertEquals("sky.environment", debug.labelOf(GL_TEXTURE, sky.environment().id()));
            assertEquals("shadow.maps", debug.labelOf(GL_TEXTURE, shadow.map().id()));
            assertEquals("water.reflection", debug.labelOf(GL_FRAMEBUFFER, water.reflectionTarget().id()));
            assertEquals("water.reflection.color",
                    debug.labelOf(GL_TEXTURE, water.reflectionTarget().color().id()));
        }
    }

    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    void anInitThatFailsHalfWayLeavesNothingBehind(TerrainSettings.World world) {
        EngineSystem failing = new EngineSystem() {
            @Override
            public SystemSpec spec() {
                return SystemSpec.named("failing").after("particles");
            }

            @Override
            public void init(EngineContext context) {
                context.own("half", Texture2D.empty(context.gl(), 4, 4, Format.RGBA8, Sampling.NEAREST_CLAMP));
                throw new IllegalStateException("no snow in assets/");
            }
        };
        List<EngineSystem> systems = new ArrayList<>(systems());
        systems.add(failing);

        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> start(systems, smallWorld(world)));

        assertEquals("no snow in assets/", e.getMessage());
        assertEquals(0, GL.context().objects().live(), "left alive: " + GL.context().objects());
    }
}

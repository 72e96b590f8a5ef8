package org.openworld.engine.shadow;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.joml.Vector3f;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.bench.FrameRecord;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.environment.SunShadow;
import org.openworld.engine.gl.Image;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.TerrainSystem;

/**
 * Maps that are not redrawn when nothing moved ({@code shadow.refresh}), on real GL over {@link WallWorld}: a kept
 * map keeps its depths (the engine does not clear a layer no view names) and its box, the picture does not change,
 * and along a moving camera path the shadows flicker no more than when every map is redrawn every frame. What is kept
 * and redrawn does not depend on the wall, so those rules are checked on the unbounded world's ground too (the tile
 * named in the parameters is the wall's imported map).
 */
@GlTest
class ShadowRefreshTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int W = 160;
    static final int H = 90;
    /** Low over the ground east of the wall, looking west along the shadow with the wall to the north. */
    static final CameraPose LOW = new CameraPose(-60, 10, 60, -60, -12, 60);
    /** How far {@link #LOW} stands over the wall world's ground, and over the unbounded world's there. */
    static final double LOW_CLEARANCE = LOW.y() - WallWorld.GROUND;

    @TempDir
    static Path dir;
    static Path wall;

    @BeforeAll
    static void writeWorld() throws IOException {
        wall = WallWorld.write(dir);
    }

    /** The wall's map (a tile), or the unbounded world. */
    static List<String> settings(TerrainSettings.World world, String... more) {
        List<String> s = new ArrayList<>(world == TerrainSettings.World.TILE ? WallWorld.terrain(wall)
                : List.of("terrain.world=" + world));
        s.addAll(List.of("shadow.resolution=256", "shadow.distance=400", "shadow.cascades=3"));
        s.addAll(List.of(more));
        return s;
    }

    static Engine engine(TerrainSettings.World world, String... more) {
        Engine engine = GlTestSupport.engine(GL.context(), W, H, settings(world, more), new CullingSystem(),
                new TerrainSystem(), new ShadowSystem());
        engine.world().setResource(WallWorld.EAST_SUN);
        return engine;
    }

    /** {@link #LOW} over this engine's ground: at the same height as over the wall world's. */
    static CameraPose low(Engine engine) {
        double ground = engine.world().resource(HeightField.class).heightAt(LOW.x(), LOW.z());
        return new CameraPose(LOW.x(), ground + LOW_CLEARANCE, LOW.z(), LOW.yaw(), LOW.pitch(), LOW.fov());
    }

    /** Renders one frame at the pose and returns its counters. */
    static Map<String, Double> frame(Engine engine, CameraPose pose) {
        engine.world().resource(Camera.class).setPose(pose);
        engine.update();
        engine.render();
        List<FrameRecord> records = new ArrayList<>();
        engine.collectFrames(true, records::add);
        return records.get(records.size() - 1).counters();
    }

    static CameraPose moved(CameraPose p, double dx, double dz, double dYaw) {
        return new CameraPose(p.x() + dx, p.y(), p.z() + dz, p.yaw() + dYaw, p.pitch(), p.fov());
    }

    static void assertSamePicture(Image a, Image b) {
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(a.channel(x, y, c), b.channel(x, y, c), "the same picture: (" + x + ", " + y + ")");
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    void anUnchangedLightAndOriginSkipTheRedrawAndAMovedOneRedraws(TerrainSettings.World world) {
        try (Engine engine = engine(world, "shadow.refresh=MOVED")) {
            CameraPose low = low(engine);
            assertEquals(3, frame(engine, low).get("shadow.redrawn"), "the first frame draws every map");
            SunShadow sun = engine.world().resource(SunShadow.class);
            float[] drawn = sun.map().read();
            Image picture = engine.readImage();
            assertEquals(0, frame(engine, low).get("shadow.redrawn"), "nothing moved: no map redrawn");
            assertArrayEquals(drawn, sun.map().read(), "the kept maps were neither cleared nor drawn over");
            assertSamePicture(picture, engine.readImage());
            // a setting changed (here the filter): the maps may no longer be what it would draw
            engine.settings().set("shadow.kernel", "5");
            assertEquals(3, frame(engine, low).get("shadow.redrawn"), "a setting changed: all redrawn");
            assertEquals(0, frame(engine, low).get("shadow.redrawn"), "and then kept again");
            // 20 m east: every box moved by whole texels (the finest is about 0.4 m, the coarsest 1.7 m)
            assertEquals(3, frame(engine, moved(low, 20, 0, 0)).get("shadow.redrawn"), "moved: all redrawn");
            // the sun turned by 1°, beyond the refresh angle (0.05°): every box turned with it
            engine.world().setResource(new Sun(new Vector3f(WallWorld.EAST_SUN.direction()).rotateY(
                    (float) Math.toRadians(1)), new Vector3f(1), new Vector3f(0.25f)));
            assertEquals(3, frame(engine, moved(low, 20, 0, 0)).get("shadow.redrawn"), "the sun turned: all");
        }
    }

    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    void aSunTurnedWithinTheRefreshAngleKeepsTheMapsAndTheirBoxes(TerrainSettings.World world) {
        ShadowSystem shadow = new ShadowSystem();
        try (Engine engine = GlTestSupport.engine(GL.context(), W, H, settings(world, "shadow.refresh=MOVED"),
                new CullingSystem(), new TerrainSystem(), shadow)) {
            engine.world().setResource(WallWorld.EAST_SUN);
            CameraPose low = low(engine);
            frame(engine, low);
            List<LightBox> drawn = shadow.boxes();
            engine.world().setResource(new Sun(new Vector3f(WallWorld.EAST_SUN.direction()).rotateY(
                    (float) Math.toRadians(0.03)), new Vector3f(1), new Vector3f(0.25f)));
            assertEquals(0, frame(engine, low).get("shadow.redrawn"));
            assertEquals(drawn, shadow.boxes(), "the maps are read through the boxes they were drawn with");
        }
    }

    /** One layer of the maps' depths. */
    static float[] layer(SunShadow sun, int i) {
        int texels = sun.map().size() * sun.map().size();
        return Arrays.copyOfRange(sun.map().read(), i * texels, (i + 1) * texels);
    }

    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    void aStaggeredFarCascadeKeepsItsDepthsAndBoxUntilItsFrame(TerrainSettings.World world) {
        ShadowSystem shadow = new ShadowSystem();
        try (Engine engine = GlTestSupport.engine(GL.context(), W, H, settings(world), new CullingSystem(),
                new TerrainSystem(), shadow)) {
            engine.world().setResource(WallWorld.EAST_SUN);
            CameraPose low = low(engine);
            // frame 1: every map drawn. Then 4 m north each frame: across the sunlight, so every box moves by more
            // than a texel (12, 4.4 and 1.1 of theirs) and each kept box still holds its slice
            assertEquals(3, frame(engine, low).get("shadow.redrawn"));
            SunShadow sun = engine.world().resource(SunShadow.class);
            List<LightBox> first = shadow.boxes();
            float[] firstNear = layer(sun, 1);
            // frame 2: cascade 2's turn (frames 2, 6, 10, ...), not cascade 1's (odd frames)
            assertEquals(2, frame(engine, moved(low, 0, -4, 0)).get("shadow.redrawn"), "cascades 0 and 2");
            List<LightBox> second = shadow.boxes();
            assertNotEquals(first.get(0), second.get(0));
            assertEquals(first.get(1), second.get(1), "cascade 1 kept: its box ...");
            assertArrayEquals(firstNear, layer(sun, 1), "... and its depths, not cleared");
            assertNotEquals(first.get(2), second.get(2));
            float[] secondFar = layer(sun, 2);
            // frame 3: cascade 1's turn; cascade 2 keeps what frame 2 drew
            assertEquals(2, frame(engine, moved(low, 0, -8, 0)).get("shadow.redrawn"), "cascades 0 and 1");
            List<LightBox> third = shadow.boxes();
            assertNotEquals(second.get(1), third.get(1));
            assertEquals(second.get(2), third.get(2));
            assertArrayEquals(secondFar, layer(sun, 2));
        }
    }

    /**
     * The mean of {@code shadow.flicker} along a camera path: 4 m north and 0.5° to the left each frame. On the wall's
     * map only: the path must see the wall's shadow move between cascades.
     */
    static double[] flickerAlongAPath(String refresh) {
        try (Engine engine = engine(TerrainSettings.World.TILE, "shadow.refresh=" + refresh, "shadow.measure=true")) {
            double flicker = 0;
            double redrawn = 0;
            int frames = 16;
            for (int f = 0; f < frames; f++) {
                Map<String, Double> counters = frame(engine, moved(LOW, 0, -4 * f, -0.5 * f));
                if (f > 0) {
                    flicker += counters.get("shadow.flicker") / (frames - 1);
                }
                redrawn += counters.get("shadow.redrawn") / frames;
            }
            return new double[] {flicker, redrawn};
        }
    }

    @Test
    void staggeredMapsFlickerNoMoreThanMapsRedrawnEveryFrame() {
        double[] always = flickerAlongAPath("ALWAYS");
        double[] staggered = flickerAlongAPath("STAGGERED");
        // doubles: a mean of whole counts, exact to round-off
        assertEquals(3, always[1], 1e-9, "ALWAYS redraws every map every frame");
        // 3 maps: the nearest every frame, the others every 2nd and 4th (1 + 1/2 + 1/4 = 1.75 a frame); 2.5 sits
        // between that and ALWAYS's 3
        assertTrue(staggered[1] < 2.5, "staggered: " + staggered[1] + " maps redrawn a frame");
        assertTrue(always[0] > 0, "the path moves some shadow between cascades");
        // 20 %: a redraw skipped moves an edge by at most a frame's worth of its shift, a small share of the flicker;
        // the band tells "no more" from "a lot more", not measured noise
        assertTrue(staggered[0] <= 1.2 * always[0], "flicker " + staggered[0] + " staggered, " + always[0]
                + " redrawn every frame");
    }
}

package org.openworld.engine.minimap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.environment.WaterLevel;
import org.openworld.engine.gl.GlObjects;
import org.openworld.engine.gl.Image;
import org.openworld.engine.testscene.TestSceneSystem;

/** The minimap on real GL, over the test scene: where it draws, its marker, north, water, rebuilds, clean-up. */
@GlTest
class MinimapSystemTest {

    static final int W = 320;
    static final int H = 180;
    /** The ground rises northwards beyond 300 m north and falls eastwards beyond 300 m east: both face from the light. */
    static final HeightField TWO_SLOPES = (x, z) -> 3 * Math.max(0, -z - 300) - 3 * Math.max(0, x - 300);

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    final MinimapSystem minimap = new MinimapSystem();

    /** The test scene with the minimap, these settings applied, the ground {@code field} and the camera at yaw. */
    Engine engine(HeightField field, double yaw, String... settings) {
        Engine engine = GlTestSupport.engine(GL.context(), W, H, List.of(settings), new TestSceneSystem(), minimap);
        place(engine, field, yaw);
        return engine;
    }

    static void place(Engine engine, HeightField field, double yaw) {
        engine.world().setResource(HeightField.class, field);
        engine.world().resource(Camera.class).setPose(new CameraPose(0, 60, 0, yaw, -10, 60));
    }

    static MinimapSettings.Square square(Engine engine) {
        return engine.settings().get(MinimapSettings.class).square(W, H);
    }

    @Test
    void turnedOnItChangesItsCornerAndNothingElse() {
        try (Engine engine = engine(TWO_SLOPES, 30)) {
            engine.render();
            Image off = engine.readImage();
            engine.settings().set("system.minimap", "on");
            engine.render();
            Image on = engine.readImage();
            MinimapSettings.Square square = square(engine);
            int changed = 0;
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    boolean differs = differs(off, on, x, y);
                    if (square.contains(x, y)) {
                        changed += differs ? 1 : 0;
                    } else {
                        assertFalse(differs, "pixel " + x + ", " + y + " outside the map changed");
                    }
                }
            }
            // 90 %: nearly all of the square; a few of the map's pixels may happen to equal the scene's beneath
            assertTrue(changed > 0.9 * square.side() * square.side(), changed + " of the map's pixels changed");
            assertEquals(MinimapSettings.Corner.BOTTOM_RIGHT, engine.settings().get(MinimapSettings.class).corner());
            assertTrue(square.left() > W / 2 && square.top() > H / 2, "in the bottom right corner");
        }
    }

    @Test
    void turnedOffItDrawsNothing() {
        Image without;
        try (Engine plain = GlTestSupport.engine(GL.context(), W, H, new TestSceneSystem())) {
            place(plain, TWO_SLOPES, 30);
            plain.render();
            without = plain.readImage();
        }
        try (Engine engine = engine(TWO_SLOPES, 30, "system.minimap=off")) {
            engine.render();
            Image off = engine.readImage();
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    assertFalse(differs(without, off, x, y), "pixel " + x + ", " + y);
                }
            }
            assertEquals(0, minimap.builds(), "no map is built while off");
        }
    }

    @Test
    void theMarkerSitsAtTheCentreAndTurnsWithTheCamera() {
        List<String> settings = List.of("system.minimap=on", "minimap.size=0.9");
        boolean[] north = new boolean[2];
        boolean[] east = new boolean[2];
        double[] yaws = {0, 90};
        for (int k = 0; k < 2; k++) {
            try (Engine engine = engine(HeightField.FLAT, yaws[k], settings.toArray(String[]::new))) {
                engine.render();
                Image image = engine.readImage();
                MinimapSettings.Square square = square(engine);
                int cx = square.left() + square.side() / 2;
                int cy = square.top() + square.side() / 2;
                // half-way from the camera to the marker's tip: inside when the marker points that way
                int reach = Math.round(0.5f * MinimapSystem.MARKER_SHARE * square.side());
                assertTrue(isMarker(image, cx, cy), "the marker at the map's centre, yaw " + yaws[k]);
                assertFalse(isMarker(image, cx, square.top() + 3), "no marker near the map's top edge");
                north[k] = isMarker(image, cx, cy - reach);
                east[k] = isMarker(image, cx + reach, cy);
            }
        }
        assertTrue(north[0] && !east[0], "yaw 0 points north, up the map");
        assertTrue(east[1] && !north[1], "yaw 90 points east, right on the map");
    }

    @Test
    void northIsUpAndEastIsRight() {
        try (Engine engine = engine(TWO_SLOPES, 0, "system.minimap=on", "minimap.size=0.9")) {
            engine.render();
            Image image = engine.readImage();
            MinimapSettings.Square square = square(engine);
            // the map's quadrants, 1 km from the camera each way (the default range shows 2 km each way)
            int quarter = square.side() / 4;
            int cx = square.left() + square.side() / 2;
            int cy = square.top() + square.side() / 2;
            double northWest = image.meanLuma(cx - quarter - 4, cy - quarter - 4, cx - quarter + 4, cy - quarter + 4);
            double northEast = image.meanLuma(cx + quarter - 4, cy - quarter - 4, cx + quarter + 4, cy - quarter + 4);
            double southWest = image.meanLuma(cx - quarter - 4, cy + quarter - 4, cx - quarter + 4, cy + quarter + 4);
            double southEast = image.meanLuma(cx + quarter - 4, cy + quarter - 4, cx + quarter + 4, cy + quarter + 4);
            // only the south-west is flat ground in the light; the slopes beyond 300 m north and east face away
            assertTrue(southWest > 1.5 * Math.max(northWest, Math.max(northEast, southEast)),
                    "lit south-west at the bottom left: NW " + northWest + " NE " + northEast + " SW " + southWest
                            + " SE " + southEast);
        }
    }

    @Test
    void groundBelowTheWaterLevelIsBlueAndTheMapFollowsTheLevel() {
        // a lake 1 km north of the camera, 20 m deep; the world's water level (as the water system writes it) says
        // where the water is
        HeightField lake = (x, z) -> Math.hypot(x, z + 1000) < 400 ? -20 : 30;
        try (Engine engine = engine(lake, 0, "system.minimap=on", "minimap.size=0.9")) {
            engine.world().setResource(new WaterLevel(0));
            engine.render();
            Image image = engine.readImage();
            MinimapSettings.Square square = square(engine);
            int cx = square.left() + square.side() / 2;
            int cy = square.top() + square.side() / 2;
            int kilometre = (int) Math.round(square.side() * 1000 / MinimapSettings.DEFAULTS.range());
            assertTrue(isBlue(image, cx, cy - kilometre), "the lake, 1 km up the map");
            assertFalse(isBlue(image, cx, cy + kilometre), "dry land 1 km south");
            // the water drained below the lake's bed: the map is built again, all land
            engine.world().setResource(new WaterLevel(-50));
            engine.render();
            assertFalse(isBlue(engine.readImage(), cx, cy - kilometre), "no lake below the level");
            assertEquals(2, minimap.builds());
        }
    }

    @Test
    void theMapIsBuiltAgainOnlyWhenTheCameraMovedAQuarterOfTheRange() {
        try (Engine engine = engine(TWO_SLOPES, 0, "system.minimap=on", "minimap.range=4000")) {
            Camera camera = engine.world().resource(Camera.class);
            List<Integer> builds = new ArrayList<>();
            for (double x : new double[] {0, 300, 900, 990, 1010, 1200}) {
                camera.setPose(new CameraPose(x, 60, 0, 0, -10, 60));
                engine.render();
                builds.add(minimap.builds());
            }
            // built at 0; 300, 900 and 990 m are within 1000 m (a quarter of 4 km); 1010 m is not; 1200 is near it
            assertEquals(List.of(1, 1, 1, 1, 2, 2), builds);
            engine.settings().set("minimap.range", "2000");
            engine.render();
            assertEquals(3, minimap.builds(), "a new range, a new map");
        }
    }

    @Test
    void itsGlObjectsAreCountedAndReleased() {
        GlObjects objects = GL.context().objects();
        int textures;
        int total;
        try (Engine plain = GlTestSupport.engine(GL.context(), W, H, new TestSceneSystem())) {
            textures = objects.live(GlObjects.Kind.TEXTURE);
            total = objects.live();
        }
        try (Engine engine = engine(TWO_SLOPES, 0, "system.minimap=on")) {
            engine.render();
            assertEquals(textures + 1, objects.live(GlObjects.Kind.TEXTURE), "one texture: the relief map");
            assertTrue(objects.live() > total + 1, "and its program and quad");
            engine.settings().set("minimap.range", "1000");
            engine.render();
            assertEquals(textures + 1, objects.live(GlObjects.Kind.TEXTURE), "a new map goes into the same texture");
        }
        assertEquals(0, objects.live(), "all released: " + objects);
    }

    static boolean differs(Image a, Image b, int x, int y) {
        for (int c = 0; c < 3; c++) {
            if (a.channel(x, y, c) != b.channel(x, y, c)) {
                return true;
            }
        }
        return false;
    }

    /** The marker's red: no land or water on the map is red. */
    static boolean isMarker(Image image, int x, int y) {
        return image.channel(x, y, 0) > 180 && image.channel(x, y, 1) < 80 && image.channel(x, y, 2) < 80;
    }

    static boolean isBlue(Image image, int x, int y) {
        return image.channel(x, y, 2) > image.channel(x, y, 0) + 60;
    }
}

package org.openworld.engine.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.environment.SnowLine;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.gl.Image;
import org.openworld.engine.sky.SkySystem;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.material.MaterialSettings;
import org.openworld.engine.terrain.material.SnowLines;

/**
 * The terrain rendered headless on small worlds: the stitching leaves no crack between levels, and the default
 * materials put snow on the heights and grass in the valleys. Pictures go to {@code target/test-images/}.
 */
@GlTest
class TerrainRenderTest {

    static final int WIDTH = 320;
    static final int HEIGHT = 180;

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    /**
     * Under either rule, levels are chosen from a point on the ground at the origin, then frozen; the camera climbs
     * and looks down at the cut from outside, 400 m over the ground 400 m south. Coloured by level with no sky
     * behind, any gap between patches (in x/z from a T-junction, or vertical from two levels disagreeing on a shared
     * vertex's height) shows the black clear colour. On both worlds; the unbounded one has no flat grid (it would
     * put every leaf of its 25 roots in the cut), so only the quadtree's two rules there. Its windows follow the
     * live camera, not the frozen point, and a node is split only where its children's blocks are resident: from
     * 600 m south the origin lies outside level 0's window (1 km, around the camera) and the cut there is coarser.
     */
    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    void everyLevelPresentAndNoCrackLetsTheBackgroundThrough(TerrainSettings.World world) throws IOException {
        // each mode with 33-vertex patches; the 17-vertex ones (up to four levels stitched on a side instead of
        // five) in the quadtree cut, the only scheme that draws them by default (the low preset)
        List<String> modes = world == TerrainSettings.World.TILE
                ? List.of("quadtree", "flat-grid", "quadtree/screen-error", "flat-grid/screen-error",
                        "quadtree/screen-error/17")
                : List.of("quadtree", "quadtree/screen-error", "quadtree/screen-error/17");
        for (String mode : modes) {
            String rule = mode.contains("screen-error") ? "screen-error" : "paper";
            String vertices = mode.endsWith("/17") ? "17" : "33";
            try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT,
                    List.of("terrain.size=256", "terrain.relief=100", "lod.patch-vertices=" + vertices,
                            "lod.base-resolution=16", "lod.pixel-error=4",
                            "lod.mode=" + mode.split("/")[0], "lod.rule=" + rule,
                            "terrain-debug.colouring=levels", "terrain-debug.freeze-lod=on", "terrain.world=" + world),
                    new TerrainSystem(), new CullingSystem())) {
                HeightField ground = engine.world().resource(HeightField.class);
                Camera camera = engine.world().resource(Camera.class);
                camera.setPose(new CameraPose(0, ground.heightAt(0, 0) + 2, 0, 0, -10, 60));
                frame(engine);
                // from outside: above the ground south of the origin, looking north and steeply down
                camera.setPose(new CameraPose(0, ground.heightAt(0, 400) + 400, 400, 0, -60, 50));
                Image image = frame(engine);
                String name = world + "-" + mode.replace('/', '-');
                image.writePng(Path.of("target/test-images/terrain-cut-" + name + ".png"));

                int background = 0;
                Set<Integer> colours = new HashSet<>();
                for (int y = 0; y < HEIGHT; y++) {
                    for (int x = 0; x < WIDTH; x++) {
                        int r = image.channel(x, y, 0), g = image.channel(x, y, 1), b = image.channel(x, y, 2);
                        if (r + g + b < 6) {
                            background++;
                        }
                        int hue = hueBucket(r, g, b);
                        if (hue >= 0) {
                            colours.add(hue);
                        }
                    }
                }
                assertEquals(0, background, name + ": pixels where the background shows through the terrain");
                // levels 0, 1 and 2 of the cut frozen at the origin lie in view (grey, unsaturated pixels are no level)
                assertTrue(colours.size() >= 3, name + ": expected at least three level colours, saw " + colours);
            }
        }
    }

    /** The snow line in metres, of the snow map's rule and then of the altitude bands', on both worlds. */
    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    void theTerrainPublishesTheSnowLineOfTheRuleInUseInMetres(TerrainSettings.World world) {
        TerrainSystem terrain = new TerrainSystem();
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT,
                List.of("terrain.size=256", "terrain.spacing=8", "terrain.snow-base=0.4", "terrain.snow-full=0.7",
                        "terrain.world=" + world),
                terrain)) {
            // the normalised height's 0 and 1: the tile's lowest and highest sample; the unbounded world, which has
            // neither, puts 0 the sea fraction of the relief below the sea and 1 the relief above that
            TerrainSettings s = TerrainSettings.DEFAULTS;
            HeightMap base = terrain.ground() instanceof TileGround tile ? tile.data().pyramid().base() : null;
            double lowest = base != null ? base.min() : -s.seaFraction() * s.relief();
            double range = base != null ? base.max() - base.min() : s.relief();
            // at init, before any update: the snow map's 40 % to 70 % of the way up
            SnowLine line = engine.world().resource(SnowLine.class);
            // 1e-3 m: the snow line from normalised heights in double, exact to round-off
            assertEquals(lowest + 0.4 * range, line.start(), 1e-3);
            assertEquals(lowest + 0.7 * range, line.full(), 1e-3);
            // the rule switched while running: the next update publishes the altitude band's line
            engine.settings().set("materials.snow-mode", "altitude-bands");
            engine.update();
            line = engine.world().resource(SnowLine.class);
            assertEquals(lowest + SnowLines.BAND_LINE * range, (line.start() + line.full()) / 2, 1e-3);
        }
    }

    /**
     * The default world (2048² samples, seed 1) from the demo's starting pose at noon, with the default materials:
     * snow (bright, grey) high in the picture, grass (green) low. The tile only: what lies in front of the camera is
     * the map's (the pose is inside the unbounded world's ground; 150 m over it a snowy hill fills the lower rows).
     */
    @Test
    void defaultWorldShowsSnowAboveAndGreenBelow() throws IOException {
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT,
                new TerrainSystem(), new CullingSystem(), new SkySystem())) {
            engine.world().setResource(new TimeOfDay(12.0, 0));
            engine.world().resource(Camera.class).setPose(new CameraPose(0, 400, 900, 0, -8, 60));
            Image image = frame(engine);
            image.writePng(Path.of("target/test-images/terrain-default-noon.png"));

            double snowRows = 0, snow = 0, greenRows = 0, green = 0;
            for (int y = 0; y < HEIGHT; y++) {
                for (int x = 0; x < WIDTH; x++) {
                    int r = image.channel(x, y, 0), g = image.channel(x, y, 1), b = image.channel(x, y, 2);
                    if (Math.min(r, Math.min(g, b)) > 170 && Math.max(r, Math.max(g, b)) - Math.min(r, Math.min(g, b)) < 40) {
                        snow++;
                        snowRows += y;
                    } else if (g > r * 1.05 && g > b * 1.05) {
                        green++;
                        greenRows += y;
                    }
                }
            }
            int pixels = WIDTH * HEIGHT;
            assertTrue(snow > pixels * 0.01, "snow covers " + snow + " pixels");
            assertTrue(green > pixels * 0.01, "grass covers " + green + " pixels");
            assertTrue(snowRows / snow < greenRows / green,
                    "snow lies above grass: mean rows " + snowRows / snow + " vs " + greenRows / green);
        }
    }

    /**
     * Culling frozen on the ground, then seen from above: only the patches inside the frozen frustum are drawn (fewer
     * than the same view culls normally), and the frozen frustum's outline shows where it was. On both worlds.
     */
    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    void frozenCullingKeepsTheOldFrustumWhenTheCameraFliesOut(TerrainSettings.World world) throws IOException {
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT,
                List.of("terrain.size=512", "terrain.spacing=8", "culling.freeze=on", "terrain-debug.freeze-lod=on",
                        "terrain.world=" + world),
                new TerrainSystem(), new CullingSystem(), new SkySystem())) {
            Camera camera = engine.world().resource(Camera.class);
            HeightField ground = engine.world().resource(HeightField.class);
            camera.setPose(new CameraPose(0, ground.heightAt(0, 600) + 30, 600, 0, 0, 60));
            frame(engine);
            camera.setPose(new CameraPose(0, 3500, 2600, 0, -50, 60));
            Image image = frame(engine);
            image.writePng(Path.of("target/test-images/terrain-frozen-culling-" + world + ".png"));
            double[] frozenPatches = new double[1];
            engine.collectFrames(true, r -> frozenPatches[0] = r.counters().get("terrain.main.patches"));

            engine.settings().set("culling.freeze", "off");
            frame(engine);
            double[] livePatches = new double[1];
            engine.collectFrames(true, r -> livePatches[0] = r.counters().get("terrain.main.patches"));
            assertTrue(frozenPatches[0] > 0 && frozenPatches[0] < livePatches[0],
                    "frozen frustum draws " + frozenPatches[0] + " patches, the live one " + livePatches[0]);
        }
    }

    /**
     * The terrain's programs are its variants, each labelled {@code terrain.} and the variant's role: once the
     * default settings drew a frame, the live programs named like a variant are exactly the ones
     * {@link TerrainVariant#all} lists for the world's layout (most not compiled yet: they compile on first use).
     */
    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    void theProgramsOwnedAreTheVariantsOfTheLayout(TerrainSettings.World world) {
        try (Engine engine = GlTestSupport.engine(GL.context(), 64, 36,
                List.of("terrain.size=256", "lod.patch-vertices=33", "terrain.world=" + world),
                new TerrainSystem(), new CullingSystem())) {
            frame(engine);
            TerrainVariant.Layout layout = world == TerrainSettings.World.TILE
                    ? TerrainVariant.Layout.TILE : TerrainVariant.Layout.CLIPMAP;
            Set<String> expected = new HashSet<>();
            for (TerrainVariant v : TerrainVariant.all(layout, MaterialSettings.DEFAULTS.cliffs())) {
                expected.add("terrain." + v.role());
            }
            Set<String> live = new HashSet<>();
            for (String label : engine.shaders().labels()) {
                if (label != null && (label.startsWith("terrain.program") || label.equals("terrain.depth"))) {
                    assertTrue(live.add(label), "one program per role: " + label);
                }
            }
            assertEquals(expected, live);
        }
    }

    private static Image frame(Engine engine) {
        engine.update();
        engine.render();
        return engine.readImage();
    }

    /** Coarse hue classes of saturated colours (the level palette); greys count as one class. */
    private static int hueBucket(int r, int g, int b) {
        int max = Math.max(r, Math.max(g, b));
        int min = Math.min(r, Math.min(g, b));
        if (max - min < 30) {
            return -1;
        }
        float[] hsb = java.awt.Color.RGBtoHSB(r, g, b, null);
        return Math.round(hsb[0] * 12) % 12;
    }
}

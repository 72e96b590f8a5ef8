package org.openworld.engine.vegetation;

import org.openworld.engine.GlTest;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.ImportedWorld;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.colour.ImageComparison;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.environment.WaterLevel;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Image;
import org.openworld.engine.shadow.ShadowSystem;
import org.openworld.engine.sky.SkySystem;
import org.openworld.engine.terrain.TerrainSystem;
import org.openworld.engine.water.WaterSystem;

/**
 * The trees on real GL, over an imported world built for the purpose: flat land 10 m above the water west of x = 0,
 * a lake bed 10 m under it to the east. Trees 12 m tall (bushes and broadleaf trees their shares of it), 10 a
 * hectare in the forest, drawn within 200 m of the viewer.
 */
@GlTest
class TreeRenderTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int W = 320;
    static final int H = 180;
    /** Samples per side of the imported map, 2 m apart: a 512 m world from −256 to 256 m. */
    static final int SAMPLES = 256;
    static final float TREE = 12;

    @TempDir
    static Path dir;
    static Path shore;

    /**
     * Normalised heights, 0 → −20 m and 1 → 80 m: 0.3 (+10 m) west of the centre, 0.1 (−10 m) east of it; one sample
     * at 0 and one at 1 in the southern corners, behind every camera here, so the range is 100 m.
     */
    @BeforeAll
    static void writeWorld() throws IOException {
        shore = writeShore(dir);
    }

    /** Writes the shore world's map into {@code folder}. */
    static Path writeShore(Path folder) throws IOException {
        return ImportedWorld.write(folder.resolve("shore.raw"), SAMPLES, (x, z) -> z == SAMPLES - 1 && x == 0 ? 0f
                : z == SAMPLES - 1 && x == SAMPLES - 1 ? 1f : x < SAMPLES / 2 ? 0.3f : 0.1f);
    }

    static List<String> settings(List<String> more) {
        List<String> s = new ArrayList<>(List.of("terrain.import-file=" + shore, "terrain.spacing=2",
                "terrain.relief=100", "terrain.sea-fraction=0.2", "vegetation.density=40", "vegetation.min-height=" + TREE,
                "vegetation.max-height=" + TREE, "vegetation.view-distance=200"));
        s.addAll(more);
        return s;
    }

    /** A sun in the east, 20° up: a 12 m tree's shadow reaches 33 m west along the ground. */
    static final Sun EAST_SUN = new Sun(new Vector3f((float) Math.cos(Math.toRadians(20)),
            (float) Math.sin(Math.toRadians(20)), 0), new Vector3f(1), new Vector3f(0.25f));

    static Engine engine(VegetationSystem trees, CameraPose pose, EngineSystem... others) {
        return engine(trees, pose, List.of(), others);
    }

    static Engine engine(VegetationSystem trees, CameraPose pose, List<String> more, EngineSystem... others) {
        return engine(GL.context(), trees, pose, more, others);
    }

    /** The shore world on another test class's context. */
    static Engine engine(GlContext gl, VegetationSystem trees, CameraPose pose, List<String> more,
                         EngineSystem... others) {
        List<EngineSystem> systems = new ArrayList<>(List.of(others));
        systems.add(new CullingSystem());
        systems.add(new TerrainSystem());
        systems.add(trees);
        Engine engine = GlTestSupport.engine(gl, W, H, settings(more), systems.toArray(EngineSystem[]::new));
        engine.world().resource(Camera.class).setPose(pose);
        engine.world().setResource(new WaterLevel(0));
        return engine;
    }

    /** Switches the trees (or another system) and draws a frame after one step. */
    static Image frame(Engine engine, String system, boolean on) {
        engine.setEnabled(system, on);
        engine.update();
        engine.render();
        return engine.readImage();
    }

    /** Where a world point lands in the picture (x, y from the top), or null outside it. */
    static int[] pixel(Engine engine, double x, double y, double z) {
        ViewCamera camera = engine.world().resource(Camera.class).view((float) W / H);
        Vector4f clip = camera.viewProjection().transform(new Vector4f((float) x, (float) y, (float) z, 1));
        if (clip.w <= 0) {
            return null;
        }
        int px = (int) Math.floor((clip.x / clip.w * 0.5 + 0.5) * W);
        int py = (int) Math.floor((0.5 - clip.y / clip.w * 0.5) * H);
        return px >= 2 && px < W - 2 && py >= 2 && py < H - 2 ? new int[] {px, py} : null;
    }

    static double luma(Image image, int[] p) {
        return image.luma(p[0], p[1]);
    }

    static boolean differs(Image a, Image b, int x, int y) {
        for (int c = 0; c < 3; c++) {
            if (Math.abs(a.channel(x, y, c) - b.channel(x, y, c)) > 2) {
                return true;
            }
        }
        return false;
    }

    @Test
    void treesStandInThePictureWhereTheyWerePlacedAndOnlyOnTheLand() {
        VegetationSystem trees = new VegetationSystem();
        // 40 m up over the land, looking west and a little down
        try (Engine engine = engine(trees, new CameraPose(-60, 40, 0, 270, -12, 60))) {
            Image off = frame(engine, "vegetation", false);
            Image on = frame(engine, "vegetation", true);
            float[] placed = trees.placed();
            int seen = 0;
            int changed = 0;
            for (int i = 0; i < placed.length; i += TreePlacement.FLOATS) {
                assertTrue(placed[i] < 0 && Math.abs(placed[i + 1] - 10) < 0.01, "a tree off the land, at x = "
                        + placed[i] + ", y = " + placed[i + 1]);
                // the crown's middle, for trees well inside the view distance
                int[] p = pixel(engine, placed[i], placed[i + 1] + 0.5 * placed[i + 3], placed[i + 2]);
                if (p != null && Math.hypot(placed[i] + 60, placed[i + 2]) < 140) {
                    seen++;
                    changed += differs(off, on, p[0], p[1]) ? 1 : 0;
                }
            }
            assertTrue(seen >= 10, "trees in view: " + seen);
            assertTrue(changed >= 0.9 * seen, "trees drawn where placed: " + changed + " of " + seen);
            // placed again only once the viewer has moved a quarter of the 200 m view distance
            int placements = trees.placements();
            engine.world().resource(Camera.class).setPose(new CameraPose(-60, 40, 45, 270, -12, 60));
            engine.update();
            assertEquals(placements, trees.placements(), "placed again after a 45 m move");
            engine.world().resource(Camera.class).setPose(new CameraPose(-60, 40, 55, 270, -12, 60));
            engine.update();
            assertEquals(placements + 1, trees.placements(), "not placed again after a 55 m move");
        }
        assertEquals(0, GL.context().objects().live(), "live GL objects after close: " + GL.context().objects());
    }

    @Test
    void treesCastShadowsOnTheGround() {
        VegetationSystem trees = new VegetationSystem();
        // straight down from 60 m above the land; the sun in the east throws the shadows west
        CameraPose above = new CameraPose(-100, 70, 0, 0, -89.9, 60);
        try (Engine engine = engine(trees, above, new ShadowSystem())) {
            engine.world().setResource(EAST_SUN);
            Image off = frame(engine, "vegetation", false);
            Image on = frame(engine, "vegetation", true);
            engine.setEnabled("shadow", false);
            Image offUnshadowed = frame(engine, "vegetation", false);
            Image onUnshadowed = frame(engine, "vegetation", true);
            float[] placed = trees.placed();
            double darker = 0;
            double covered = 0;
            int points = 0;
            for (int i = 0; i < placed.length; i += TreePlacement.FLOATS) {
                // the ground west of a tree east of the centre, in its shadow and clear of the tree itself, which the
                // perspective leans eastwards: 0.8 heights for a conifer (the sun's ray there passes 0.29 heights
                // up, through the lowest cones, and the crown reaches 0.35 heights), 1.2 for a broadleaf tree (0.44
                // up, through its crown, which reaches 0.52); bushes are too low to leave their own outline
                TreeKind kind = TreePlacementTest.kindOf(trees.layout(), i / TreePlacement.FLOATS);
                if (placed[i] < above.x() + 5 || kind == TreeKind.BUSH) {
                    continue;
                }
                double west = (kind == TreeKind.CONIFER ? 0.8 : 1.2) * placed[i + 3];
                int[] p = pixel(engine, placed[i] - west, placed[i + 1], placed[i + 2]);
                if (p != null) {
                    darker += luma(off, p) - luma(on, p);
                    covered += Math.abs(luma(offUnshadowed, p) - luma(onUnshadowed, p));
                    points++;
                }
            }
            assertTrue(points >= 3, "shadow points in view: " + points);
            assertTrue(darker / points > 15, "the ground in the trees' shadows darkened by " + darker / points);
            assertTrue(covered / points < 3, "without shadow maps the same ground changed by " + covered / points
                    + ": the points are not clear of the trees");
        }
    }

    @Test
    void treesAppearInTheWatersReflection() {
        VegetationSystem trees = new VegetationSystem();
        WaterSystem water = new WaterSystem();
        // 15 m over the lake, 80 m east of the shore, looking west at it
        List<String> calm = List.of("clouds.cover=0", "water.reflection=FULL", "water.wind=0.5", "vegetation.density=100");
        try (Engine engine = engine(trees, new CameraPose(80, 15, 0, 270, -4, 60), calm, new SkySystem(), water)) {
            frame(engine, "vegetation", false);
            Image off = water.reflectionTarget().read();
            frame(engine, "vegetation", true);
            Image on = water.reflectionTarget().read();
            float[] placed = trees.placed();
            int seen = 0;
            int changed = 0;
            for (int i = 0; i < placed.length; i += TreePlacement.FLOATS) {
                // The mirror camera is the viewer's with y flipped (its oblique near plane changes depth alone), so
                // a point shows in the reflection where the viewer would see its mirror image below the water. The
                // crown at 0.7 heights of a tree within 20 m of the shore clears the bank in the mirror's view.
                if (placed[i] < -20 || TreePlacementTest.kindOf(trees.layout(), i / TreePlacement.FLOATS)
                        == TreeKind.BUSH) {
                    continue; // a bush's crown, 2 m up, stays behind the bank
                }
                int[] p = pixel(engine, placed[i], -(placed[i + 1] + 0.7 * placed[i + 3]), placed[i + 2]);
                if (p != null) {
                    seen++;
                    changed += differs(off, on, p[0], p[1]) ? 1 : 0;
                }
            }
            assertTrue(seen >= 5, "trees by the shore in the reflection's view: " + seen);
            assertTrue(changed >= 0.9 * seen, "trees seen in the reflection: " + changed + " of " + seen);
        }
    }

    /** The default switch distance, metres: the camera stands this far from the nearest plant. */
    static final double SWITCH = VegetationSettings.DEFAULTS.lodDistance();
    /**
     * The largest mean ΔE00 allowed between the two shapes over the pixels of the plants. A difference of 2.3 is
     * just noticeable side by side; the dithered cross-fade spreads the change over 30 m of walking, so a plant is
     * never seen in both shapes at once: a mean of twice that (plants a few pixels wide, whose edge pixels turn from
     * plant to ground, count for most of it) passes unseen.
     */
    static final double MEAN_BOUND = 4.6;

    static Image draw(Engine engine, boolean on, double lodDistance) {
        // no impostors, the farthest they may be: the first switch alone
        engine.settings().set("vegetation.impostor-distance", "5000");
        engine.settings().set("vegetation.lod-distance", String.valueOf(lodDistance));
        return frame(engine, "vegetation", on);
    }

    /**
     * The two shapes of every kind, full and simplified, seen at the distance where one gives way to the other: from a
     * camera above the lake 150 m east of the shore (the default switch distance), so every plant in view stands
     * 150 m or more away. The same frame is drawn with every plant in its full shape ({@code vegetation.lod-distance}
     * far beyond the view) and with every plant simplified (the switch at the smallest distance allowed), and the
     * two pictures are compared where either has a plant.
     */
    @Test
    void theFullAndTheSimplifiedShapesLookAlikeAtTheSwitchDistance() {
        VegetationSystem plants = new VegetationSystem();
        // 12 m over the lake, looking west at the shore and the land behind it, a little down
        // snow from 10.5 m, certain at 19.5 m: the tree line at 15 m, 5 m above the land, which stands 62 % of the
        // way up from the shore to it, where the zones grow a mixed forest of mostly conifers (PlacementField), as
        // on the upper slopes most forests stand; the land lies below the line's band, so every plant is full-grown
        List<String> more = List.of("vegetation.density=150", "vegetation.view-distance=1000", "terrain.snow-base=0.305",
                "terrain.snow-full=0.395");
        // with the sky behind them, as the switch is seen (against black, every edge pixel would count double)
        try (Engine engine = engine(plants, new CameraPose(SWITCH, 12, 0, 270, -2, 60), more, new SkySystem())) {
            Image bare = draw(engine, false, SWITCH);
            Image full = draw(engine, true, 5000);
            Image simple = draw(engine, true, 10);
            double sum = 0;
            int pixels = 0;
            ImageComparison between = ImageComparison.of(full, simple);
            ImageComparison fullOnBare = ImageComparison.of(full, bare);
            ImageComparison simpleOnBare = ImageComparison.of(simple, bare);
            double plantOnGround = 0;
            for (int y = 0; y < full.height(); y++) {
                for (int x = 0; x < full.width(); x++) {
                    // a pixel of a plant in either picture: noticeably (ΔE00 over 2.3) unlike the bare ground
                    if (fullOnBare.deltaE(x, y) > 2.3 || simpleOnBare.deltaE(x, y) > 2.3) {
                        sum += between.deltaE(x, y);
                        plantOnGround += Math.max(fullOnBare.deltaE(x, y), simpleOnBare.deltaE(x, y));
                        pixels++;
                    }
                }
            }
            assertTrue(pixels > 200, "plant pixels: " + pixels);
            double mean = sum / pixels;
            // the plants themselves stand out from the ground far more than the shapes differ: the test sees them
            assertTrue(plantOnGround / pixels > 3 * mean, "plants against the ground " + plantOnGround / pixels
                    + ", the shapes against each other " + mean);
            assertTrue(mean < MEAN_BOUND, "mean ΔE00 between the full and the simplified shapes at " + SWITCH
                    + " m, over " + pixels + " plant pixels: " + mean);
        }
        assertEquals(0, GL.context().objects().live(), "live GL objects after close: " + GL.context().objects());
    }
}

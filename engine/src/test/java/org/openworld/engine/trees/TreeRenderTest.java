package org.openworld.engine.trees;

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
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.environment.WaterLevel;
import org.openworld.engine.gl.Image;
import org.openworld.engine.shadow.ShadowSystem;
import org.openworld.engine.sky.SkySystem;
import org.openworld.engine.terrain.TerrainSystem;
import org.openworld.engine.water.WaterSystem;

/**
 * The trees on real GL, over an imported world built for the purpose: flat land 10 m above the water west of x = 0,
 * a lake bed 10 m under it to the east. Trees 12 m tall, 10 a hectare, drawn within 200 m of the viewer.
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
        shore = ImportedWorld.write(dir.resolve("shore.raw"), SAMPLES, (x, z) -> z == SAMPLES - 1 && x == 0 ? 0f
                : z == SAMPLES - 1 && x == SAMPLES - 1 ? 1f : x < SAMPLES / 2 ? 0.3f : 0.1f);
    }

    static List<String> settings(List<String> more) {
        List<String> s = new ArrayList<>(List.of("terrain.import-file=" + shore, "terrain.spacing=2",
                "terrain.relief=100", "terrain.sea-fraction=0.2", "trees.density=10", "trees.min-height=" + TREE,
                "trees.max-height=" + TREE, "trees.view-distance=200"));
        s.addAll(more);
        return s;
    }

    /** A sun in the east, 20° up: a 12 m tree's shadow reaches 33 m west along the ground. */
    static final Sun EAST_SUN = new Sun(new Vector3f((float) Math.cos(Math.toRadians(20)),
            (float) Math.sin(Math.toRadians(20)), 0), new Vector3f(1), new Vector3f(0.25f));

    static Engine engine(TreeSystem trees, CameraPose pose, EngineSystem... others) {
        return engine(trees, pose, List.of(), others);
    }

    static Engine engine(TreeSystem trees, CameraPose pose, List<String> more, EngineSystem... others) {
        List<EngineSystem> systems = new ArrayList<>(List.of(others));
        systems.add(new CullingSystem());
        systems.add(new TerrainSystem());
        systems.add(trees);
        Engine engine = GlTestSupport.engine(GL.context(), W, H, settings(more), systems.toArray(EngineSystem[]::new));
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
        TreeSystem trees = new TreeSystem();
        // 40 m up over the land, looking west and a little down
        try (Engine engine = engine(trees, new CameraPose(-60, 40, 0, 270, -12, 60))) {
            Image off = frame(engine, "trees", false);
            Image on = frame(engine, "trees", true);
            float[] placed = trees.placed();
            int seen = 0;
            int changed = 0;
            for (int i = 0; i < placed.length; i += TreePlacement.FLOATS) {
                assertTrue(placed[i] < 0 && Math.abs(placed[i + 1] - 10) < 0.01, "a tree off the land, at x = "
                        + placed[i] + ", y = " + placed[i + 1]);
                // the crown's middle, for trees well inside the view distance
                int[] p = pixel(engine, placed[i], placed[i + 1] + 0.5 * TREE, placed[i + 2]);
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
        TreeSystem trees = new TreeSystem();
        // straight down from 60 m above the land; the sun in the east throws the shadows west
        CameraPose above = new CameraPose(-100, 70, 0, 0, -89.9, 60);
        try (Engine engine = engine(trees, above, new ShadowSystem())) {
            engine.world().setResource(EAST_SUN);
            Image off = frame(engine, "trees", false);
            Image on = frame(engine, "trees", true);
            engine.setEnabled("shadow", false);
            Image offUnshadowed = frame(engine, "trees", false);
            Image onUnshadowed = frame(engine, "trees", true);
            float[] placed = trees.placed();
            double darker = 0;
            double covered = 0;
            int points = 0;
            for (int i = 0; i < placed.length; i += TreePlacement.FLOATS) {
                // the ground 0.8 heights west of a tree east of the centre: in its shadow (the crown there is 0.16
                // heights wide), and clear of the tree itself, which the perspective leans eastwards
                if (placed[i] < above.x() + 5) {
                    continue;
                }
                int[] p = pixel(engine, placed[i] - 0.8 * TREE, placed[i + 1], placed[i + 2]);
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
        TreeSystem trees = new TreeSystem();
        WaterSystem water = new WaterSystem();
        // 15 m over the lake, 80 m east of the shore, looking west at it
        List<String> calm = List.of("clouds.cover=0", "water.reflection=FULL", "water.wind=0.5", "trees.density=40");
        try (Engine engine = engine(trees, new CameraPose(80, 15, 0, 270, -4, 60), calm, new SkySystem(), water)) {
            frame(engine, "trees", false);
            Image off = water.reflectionTarget().read();
            frame(engine, "trees", true);
            Image on = water.reflectionTarget().read();
            float[] placed = trees.placed();
            int seen = 0;
            int changed = 0;
            for (int i = 0; i < placed.length; i += TreePlacement.FLOATS) {
                // The mirror camera is the viewer's with y flipped (its oblique near plane changes depth alone), so
                // a point shows in the reflection where the viewer would see its mirror image below the water. The
                // crown at 0.7 heights of a tree within 20 m of the shore clears the bank in the mirror's view.
                if (placed[i] < -20) {
                    continue;
                }
                int[] p = pixel(engine, placed[i], -(placed[i + 1] + 0.7 * TREE), placed[i + 2]);
                if (p != null) {
                    seen++;
                    changed += differs(off, on, p[0], p[1]) ? 1 : 0;
                }
            }
            assertTrue(seen >= 5, "trees by the shore in the reflection's view: " + seen);
            assertTrue(changed >= 0.9 * seen, "trees seen in the reflection: " + changed + " of " + seen);
        }
    }
}

package org.openworld.engine.terrain.stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.gl.Image;
import org.openworld.engine.terrain.DepthReader;
import org.openworld.engine.terrain.TerrainSystem;
import org.openworld.engine.terrain.heights.BandedHeights;

/**
 * The unbounded world drawn headless ({@code terrain.world=unbounded}): a fast flight streams its levels without
 * ever showing a hole, and a place looks the same whatever flight led there. With no sky system the clear colour is
 * black, so the background shows wherever no terrain was drawn. Pictures go to {@code target/test-images/}.
 */
@GlTest
class UnboundedWorldTest {

    static final int WIDTH = 320;
    static final int HEIGHT = 180;
    /** The default budget: 512² samples a level, so the level-0 window is 1 km across and a fast flight outruns it. */
    static final List<String> SETTINGS = List.of("terrain.world=unbounded");
    /** Rows whose view ray points at least this far below the horizon must show ground (see the first test). */
    static final double BELOW_HORIZON_DEG = 4;

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    /**
     * Flying east at 60 m a step (3.6 km/s at 60 steps a second, twelve times the crossing path's speed), 300 m over
     * the ground and looking 10° down, for 150 steps (9 km): the windows lag behind and their new blocks arrive a
     * few a frame, so the cut falls back on coarser levels, but every pixel whose ray points 4° or more below the
     * horizon (such a ray meets the ground within 1100 m / sin 4° = 16 km, inside the roots drawn) shows terrain.
     * The check would see a hole: a root left undrawn, a node drawn before its heights arrived (a spike to the
     * uninitialised 0 and back), or a crack.
     */
    @Test
    void aFastFlightDrawsNoHoleBelowTheHorizon() throws IOException {
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT, SETTINGS, new TerrainSystem(),
                new CullingSystem())) {
            HeightField ground = engine.world().resource(HeightField.class);
            Camera camera = engine.world().resource(Camera.class);
            double fov = 60;
            int firstGroundRow = firstRowBelow(-10, fov, BELOW_HORIZON_DEG);
            int coarser = 0;
            for (int step = 0; step < 150; step++) {
                double x = -4000 + 60.0 * step;
                camera.setPose(new CameraPose(x, ground.heightAt(x, 500) + 300, 500, 90, -10, fov));
                Image image = frame(engine);
                int holes = 0;
                for (int y = firstGroundRow; y < HEIGHT; y++) {
                    for (int px = 0; px < WIDTH; px++) {
                        if (image.channel(px, y, 0) + image.channel(px, y, 1) + image.channel(px, y, 2) < 3) {
                            holes++;
                        }
                    }
                }
                if (holes > 0) {
                    image.writePng(Path.of("target/test-images/unbounded-hole-" + step + ".png"));
                }
                assertEquals(0, holes, "background pixels below the horizon at step " + step + " (x = " + x + ")");
                if (step == 149) {
                    image.writePng(Path.of("target/test-images/unbounded-flight.png"));
                }
            }
        }
    }

    /**
     * What is drawn is the world's heights, also while the windows stream behind a camera that outruns them: flying
     * east at 200 m a step (just under the jump that would make it wait) 300 m over the ground, for 40 steps, the
     * scene's depth is read back and turned into world points within 1 km of the eye, and nearly every point lies on
     * the surface of one of the world's levels (the triangles through its samples, {@link BandedHeights#height}),
     * to the depth's rounding: whichever level the cut fell back on, it is the world's. The rest, about 12 %, lie in
     * patches' outer rings (124 of a patch's 1024 cells), whose fans are no level's triangles. Measured: 88 % on a
     * level; with every node taken as resident (the residency check left out) 58 %, as nodes drawn before their
     * heights arrived read texels still holding the place a window's width behind (or NaN if never written).
     * Geomorphing is off here: it draws a patch part of the way between two levels, on neither.
     */
    @Test
    void theGroundDrawnIsTheWorldsWhileItStreams() {
        DepthReader reader = new DepthReader();
        List<String> settings = new ArrayList<>(SETTINGS);
        settings.add("lod.morph=off");
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT, settings, new TerrainSystem(),
                new CullingSystem(), reader)) {
            BandedHeights world = (BandedHeights) engine.world().resource(HeightField.class);
            Camera camera = engine.world().resource(Camera.class);
            int checked = 0;
            int onALevel = 0;
            int[] byLevel = new int[world.levels()];
            for (int step = 0; step < 40; step++) {
                double x = -6000 + 200.0 * step;
                camera.setPose(new CameraPose(x, world.heightAt(x, -800) + 300, -800, 90, -25, 60));
                frame(engine);
                for (int y = 0; y < HEIGHT; y += 8) {
                    for (int px = 0; px < WIDTH; px += 8) {
                        Vector3f p = reader.point(px, y);
                        if (p == null || p.distance(reader.eye) > 1000) {
                            continue;
                        }
                        assertTrue(Float.isFinite(p.y), "a NaN height drawn at step " + step);
                        double d = p.distance(reader.eye);
                        int level = levelUnder(world, p, 0.05 + 3e-7 * d * d);
                        checked++;
                        if (level >= 0) {
                            onALevel++;
                            byLevel[level]++;
                        }
                    }
                }
            }
            String seen = onALevel + " of " + checked + " points on a level, by level "
                    + java.util.Arrays.toString(byLevel);
            // 5 000 points: enough depth read-backs over the 40 steps to judge a share; 0.8 is the share chosen for
            // "most points on a level", not derived
            assertTrue(checked > 5000, seen);
            assertTrue(onALevel >= 0.8 * checked, seen);
        }
    }

    /** The finest level whose triangles pass within {@code tolerance} metres of {@code p} vertically, or −1. */
    private static int levelUnder(BandedHeights world, Vector3f p, double tolerance) {
        for (int level = 0; level < world.levels(); level++) {
            if (Math.abs(p.y - world.surface(level, p.x, p.z)) <= tolerance) {
                return level;
            }
        }
        return -1;
    }

    /**
     * The same pose after two different flights (due east, and a zigzag from the north-west), once the windows
     * have caught up, gives the same picture pixel for pixel: what is drawn depends on the place, not on the way
     * there or on what was streamed before. A stale block, a texel addressed by the window's position instead of
     * the world's, or heights made in another order would show.
     */
    @Test
    void aPlaceLooksTheSameWhateverTheFlight() throws IOException {
        CameraPose end = new CameraPose(2500, 0, 1200, 45, -12, 60);
        Image east = afterFlight(end, step -> new double[] {-3000 + 55.0 * step, 1200});
        Image zigzag = afterFlight(end, step -> new double[] {-2000 + 45.0 * step, 1200 + (step % 2 == 0 ? 90 : -90)});
        east.writePng(Path.of("target/test-images/unbounded-after-east.png"));
        zigzag.writePng(Path.of("target/test-images/unbounded-after-zigzag.png"));
        int differ = 0;
        int ground = 0;
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                for (int c = 0; c < 3; c++) {
                    if (east.channel(x, y, c) != zigzag.channel(x, y, c)) {
                        differ++;
                        break;
                    }
                }
                ground += east.channel(x, y, 0) + east.channel(x, y, 1) + east.channel(x, y, 2) >= 3 ? 1 : 0;
            }
        }
        assertTrue(ground > WIDTH * HEIGHT / 2, "the end pose looks at the ground: " + ground + " pixels");
        assertEquals(0, differ, "pixels that differ between the two flights");
    }

    /**
     * The streamed snow map reaches the picture: over the snow line the view from above is much brighter with the
     * default snow rule than with snow moved beyond the highest ground (snow-base 0.99), all else equal. With the
     * snow texture unread, or read from the wrong level or place, the two would match.
     */
    @Test
    void theStreamedSnowShows() {
        double withSnow = meanLuma(List.of());
        double without = meanLuma(List.of("terrain.snow-full=1", "terrain.snow-base=0.99"));
        assertTrue(withSnow > without + 20, "mean luma with snow " + withSnow + ", without " + without);
    }

    private static double meanLuma(List<String> more) {
        List<String> settings = new ArrayList<>(SETTINGS);
        settings.addAll(more);
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT, settings, new TerrainSystem(),
                new CullingSystem())) {
            HeightField ground = engine.world().resource(HeightField.class);
            // the highest ground along a line: snow there whatever the seed's luck
            double bestX = 0;
            for (double x = 0; x < 20_000; x += 100) {
                bestX = ground.heightAt(x, 0) > ground.heightAt(bestX, 0) ? x : bestX;
            }
            engine.world().resource(Camera.class).setPose(new CameraPose(bestX, ground.heightAt(bestX, 0) + 400, 0,
                    0, -89, 60));
            Image image = frame(engine);
            double sum = 0;
            for (int y = 0; y < HEIGHT; y++) {
                for (int x = 0; x < WIDTH; x++) {
                    sum += 0.2126 * image.channel(x, y, 0) + 0.7152 * image.channel(x, y, 1)
                            + 0.0722 * image.channel(x, y, 2);
                }
            }
            return sum / (WIDTH * HEIGHT);
        }
    }

    /** Flies 100 steps along {@code path} (x, z by step, 300 m over the ground), then hovers at {@code end}. */
    private static Image afterFlight(CameraPose end, java.util.function.IntFunction<double[]> path) {
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT, SETTINGS, new TerrainSystem(),
                new CullingSystem())) {
            HeightField ground = engine.world().resource(HeightField.class);
            Camera camera = engine.world().resource(Camera.class);
            for (int step = 0; step < 100; step++) {
                double[] p = path.apply(step);
                camera.setPose(new CameraPose(p[0], ground.heightAt(p[0], p[1]) + 300, p[1], 90, -10, 60));
                frame(engine);
            }
            CameraPose there = new CameraPose(end.x(), ground.heightAt(end.x(), end.z()) + 250, end.z(), end.yaw(),
                    end.pitch(), end.fov());
            camera.setPose(there);
            Image image = null;
            for (int hover = 0; hover < 200; hover++) { // the windows catch up; what is drawn is shaded first
                image = frame(engine);
            }
            return image;
        }
    }

    /** The first image row whose ray points at least {@code below} degrees under the horizon, for this pitch. */
    private static int firstRowBelow(double pitchDeg, double fovDeg, double below) {
        double halfHeight = Math.tan(Math.toRadians(fovDeg / 2));
        double t = Math.tan(Math.toRadians(-below - pitchDeg)); // the ray's angle from the view axis, up positive
        return (int) Math.ceil((0.5 - 0.5 * t / halfHeight) * HEIGHT);
    }

    private static Image frame(Engine engine) {
        engine.update();
        engine.render();
        return engine.readImage();
    }
}

package org.openworld.engine.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.gl.Image;

/**
 * The ground reaches the horizon ({@link FarField}): seen from high up, no pixel below the terrain's horizon line
 * shows the background. With no sky system the clear colour is black, so the background shows wherever no ground
 * was drawn. Pictures go to {@code target/test-images/}.
 *
 * <p><b>The horizon line tested.</b> On a planet of radius R ({@link FarField#PLANET_RADIUS}) an eye at height h
 * sees a sphere of radius R + g down to the ray tangent to it, {@code acos((R + g) / (R + h))} below the horizontal.
 * Take g the lowest ground the world can hold (the bands' bound, or the tile's lowest sample): a ray that points
 * further down passes below the whole sphere of that height within {@code sqrt(2 R (h − g))} (193 km for
 * h = 2000 m and g = −944 m), so it must meet the ground before, whatever the relief; its pixel may not be
 * background. The line depends on the eye's height alone, so every pixel is checked by its own ray (its column as
 * well as its row: a pitched view's horizon is not a row), through the pixel's centre, which is what rasterising
 * tests. No tolerance is added: the drawn ring lies above the true sphere between its vertices (chords of a circle
 * lie inside it, so nearer and higher), which only covers more.
 */
@GlTest
class FarFieldTest {

    static final int WIDTH = 240;
    static final int HEIGHT = 135;
    static final double FOV = 60;

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    /** The unbounded world from 2000 m, level and 4° down, and from 8000 m (horizon 320 km and more). */
    @Test
    void theUnboundedWorldReachesTheHorizon() throws IOException {
        TerrainSystem terrain = new TerrainSystem();
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT, List.of("terrain.world=unbounded"),
                terrain, new CullingSystem())) {
            double lowest = terrain.ground().heights().lowest();
            check(engine, new CameraPose(0, 2000, 0, 300, -4, FOV), lowest, "unbounded-2000m-down");
            check(engine, new CameraPose(0, 2000, 0, 300, 0, FOV), lowest, "unbounded-2000m-level");
            check(engine, new CameraPose(0, 8000, 0, 300, -4, FOV), lowest, "unbounded-8000m");
        }
    }

    /** The tile's copies from 2000 m: the ring reads its pyramid, so it goes on as the copies would. */
    @Test
    void theTileReachesTheHorizon() throws IOException {
        TerrainSystem terrain = new TerrainSystem();
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT,
                List.of("terrain.world=tile", "terrain.size=512"), terrain, new CullingSystem())) {
            double lowest = terrain.ground().heights().lowest();
            check(engine, new CameraPose(0, 2000, 0, 300, -4, FOV), lowest, "tile-2000m");
        }
    }

    /** Renders the pose and counts background pixels whose ray points below the horizon line of {@code lowest}. */
    private static void check(Engine engine, CameraPose pose, double lowest, String name) throws IOException {
        engine.world().resource(Camera.class).setPose(pose);
        engine.update();
        engine.render();
        Image image = engine.readImage();
        double r = FarField.PLANET_RADIUS;
        double horizon = Math.acos((r + lowest) / (r + pose.y())); // radians below the horizontal
        ViewCamera view = ViewCamera.perspective(pose, WIDTH / (float) HEIGHT, Camera.NEAR, Camera.FAR);
        Matrix4f toWorld = new Matrix4f(view.viewProjection()).invert();
        Vector3f ray = new Vector3f();
        int checked = 0;
        int background = 0;
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                // the pixel centre's ray: the far plane's point under it, less the eye (image row 0 is the top)
                toWorld.transformProject((x + 0.5f) / WIDTH * 2 - 1, 1 - (y + 0.5f) / HEIGHT * 2, 1, ray)
                        .sub(view.position()).normalize();
                if (Math.asin(ray.y) >= -horizon) {
                    continue;
                }
                checked++;
                if (image.channel(x, y, 0) + image.channel(x, y, 1) + image.channel(x, y, 2) < 3) {
                    background++;
                }
            }
        }
        image.writePng(Path.of("target/test-images/far-field-" + name + ".png"));
        assertTrue(checked > WIDTH * HEIGHT / 10, name + ": only " + checked + " pixels below the horizon line");
        assertEquals(0, background, name + ": " + background + " of the " + checked + " pixels below the horizon line "
                + "(" + Math.toDegrees(horizon) + "° down) show the background");
    }
}

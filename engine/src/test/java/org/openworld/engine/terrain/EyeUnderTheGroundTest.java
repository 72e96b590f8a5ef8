package org.openworld.engine.terrain;

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
import org.openworld.engine.bench.FrameRecord;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraController;
import org.openworld.engine.camera.CameraDirection;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.camera.CameraSystem;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.terrain.lod.LodSettings;

/**
 * A pose whose eye lies inside a hill: seen from below, the ground's back faces are culled and only the slopes
 * turned towards the eye are drawn, ribbons of grass and rock hanging over the lake. Whatever directs the camera, the
 * director keeps the eye above the ground, so each pixel shows the first ground its ray meets: marched from the eye
 * towards the point drawn, the ray never passes under the ground before it. The tile of seed 1 at its default size,
 * the eye 47 m under the hillside at (−600, 500), looking north-north-west over the lake.
 */
@GlTest
class EyeUnderTheGroundTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int W = 240;
    static final int H = 135;
    static final CameraPose INSIDE_THE_HILL = new CameraPose(-600, 200, 500, 330, -10, 60);

    /**
     * Metres the ray may pass under the height field: the drawn mesh is the field's triangles, not its bilinear
     * surface (half a metre covers that on this relief, as {@code ShadowStatistics.GROUND_METRES} does), and a
     * patch drawn coarse departs from the finest heights by its geometric error, at most
     * {@code lod.pixel-error} pixels at its distance, {@code p · d / f} metres at distance d for a focal length of f
     * pixels (see {@link #screenError}).
     */
    static final double MESH_METRES = 0.5;
    /** Metres between the march's samples: the tile's spacing, 2 m, so no ridge between samples is missed. */
    static final double MARCH_STEP = 2;

    @Test
    void theEyeIsLiftedOutOfTheGroundAndEveryPixelIsTheFirstGroundItsRayMeets() throws IOException {
        DepthReader reader = new DepthReader();
        List<FrameRecord> records = new ArrayList<>();
        try (Engine engine = GlTestSupport.engine(GL.context(), W, H, List.of("terrain.world=tile"),
                new CameraSystem(), new TerrainSystem(), new CullingSystem(), reader)) {
            HeightField ground = engine.world().resource(HeightField.class);
            double below = ground.heightAt(INSIDE_THE_HILL.x(), INSIDE_THE_HILL.z()) - INSIDE_THE_HILL.y();
            // 10 m under the surface: far more than the near plane's distance, so the lift is not a rounding
            assertTrue(below > 10, "the pose is inside the hill: " + below + " m under its surface");
            engine.world().setResource(CameraDirection.class, CameraDirection.fixed(INSIDE_THE_HILL));
            engine.update();
            engine.render();
            engine.readImage().writePng(Path.of("target/test-images/eye-under-the-ground.png"));
            engine.collectFrames(true, records::add);
            CameraPose eye = engine.world().resource(Camera.class).pose();

            // every pixel: the first ground along its ray
            double focal = H / 2.0 / Math.tan(Math.toRadians(eye.fov() / 2));
            int drawn = 0;
            int hidden = 0;
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    Vector3f p = reader.point(x, y);
                    if (p == null) {
                        continue;
                    }
                    drawn++;
                    hidden += passesUnderTheGround(ground, reader.eye, p, focal) ? 1 : 0;
                }
            }
            System.out.println("eye under the ground: " + hidden + " of " + drawn + " pixels behind nearer ground");
            assertTrue(drawn > W * H / 4, "the ground in view: " + drawn + " pixels");
            assertEquals(0, hidden, "pixels showing ground that nearer ground hides");

            // the director's floor, and its report
            double floor = ground.heightAt(eye.x(), eye.z()) + CameraController.MIN_CLEARANCE;
            // doubles: the same sum computed twice, equal to round-off
            assertEquals(floor, eye.y(), 1e-9, "the eye lifted to the near plane's distance above the ground");
            assertEquals(floor - INSIDE_THE_HILL.y(), records.get(0).counters().get(CameraSystem.LIFTED.name()), 1e-9);
        }
    }

    /** The most metres a drawn patch departs from the finest heights at distance d: {@code p · d / f}. */
    static double screenError(double distance, double focal) {
        return LodSettings.DEFAULTS.pixelError() * distance / focal;
    }

    /** Whether the ray from the eye to p passes under the ground, by more than the mesh's own departure, before p. */
    static boolean passesUnderTheGround(HeightField ground, Vector3f eye, Vector3f p, double focal) {
        double length = eye.distance(p);
        for (double t = MARCH_STEP; t < length - MARCH_STEP; t += MARCH_STEP) {
            double f = t / length;
            double x = eye.x + (p.x - eye.x) * f;
            double y = eye.y + (p.y - eye.y) * f;
            double z = eye.z + (p.z - eye.z) * f;
            if (ground.heightAt(x, z) > y + MESH_METRES + screenError(t, focal)) {
                return true;
            }
        }
        return false;
    }
}

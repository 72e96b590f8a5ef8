package org.openworld.engine.terrain;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.ImportedWorld;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.gl.Image;

/**
 * A cliff shows its rock as finely as level ground does: a wall world whose 70° face rises eastwards from
 * a floor to a level rock plateau, the face seen head-on and the plateau straight down, both from 10 m, with the
 * normal and gloss maps off so the pictures show the rock's albedo. The texel density along a picture's rows and
 * columns is measured as the mean luma step between neighbouring pixels there; the face's rows run across it and its
 * columns down its fall line, the plateau's along the same texture axes. Projected from above, the face's texture
 * is stretched by 1 / cos 70° = 2.9 down the fall line, so its steps there shrink against the plateau's; projected
 * along X (materials.cliffs=triplanar) it is not. Pictures go to {@code target/test-images/cliff-*.png}.
 */
@GlTest
class CliffTexelsTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int W = 320;
    static final int H = 240;
    static final int SAMPLES = 256;
    /** The face: 70° between x = −20 and 20 m, from the floor at 0 m to the plateau at 110 m. */
    static final double SLOPE = Math.toRadians(70);
    static final double FACE_TOP = 40 * Math.tan(SLOPE);
    /** The highest sample (a corner) puts the plateau at 0.69 of the relief: rock by height, below the snow. */
    static final double PEAK = 160;
    /** Metres from the eye to the surface, along its normal. */
    static final double DISTANCE = 10;

    @TempDir
    static Path dir;
    static Path cliff;

    /** 256 m square, 1 m between samples; the face runs north-south. */
    @BeforeAll
    static void writeWorld() throws IOException {
        cliff = ImportedWorld.write(dir.resolve("cliff.raw"), SAMPLES, (x, z) -> {
            double metres = x - SAMPLES / 2.0;
            double h = Math.min(FACE_TOP, Math.max(0, (metres + 20) * Math.tan(SLOPE)));
            return (float) (x == 0 && z == 0 ? PEAK : h);
        });
    }

    /** Texel density of one picture: mean luma steps along the rows and down the columns, over the mean luma. */
    record Density(double across, double down) {
    }

    /** The face head-on and the plateau from above under {@code cliffs}: density down the face over the plateau's. */
    static double faceOverGround(String cliffs) throws IOException {
        List<String> settings = new ArrayList<>(List.of("terrain.import-file=" + cliff, "terrain.spacing=1",
                "terrain.relief=" + PEAK, "terrain.sea-fraction=0", "terrain.snow-full=1", "terrain.snow-base=0.9",
                "materials.normal-map=off", "materials.gloss-map=off", "materials.cliffs=" + cliffs));
        try (Engine engine = GlTestSupport.engine(GL.context(), W, H, settings, new TerrainSystem(),
                new CullingSystem())) {
            engine.world().setResource(new TimeOfDay(12.0, 0));
            // the face's middle (0, 55, 0) faces west and 20° up: the eye on its normal, looking east 20° down
            double nx = -Math.sin(SLOPE);
            double ny = Math.cos(SLOPE);
            Density face = density(engine, "face-" + cliffs, new CameraPose(DISTANCE * nx, FACE_TOP / 2
                    + DISTANCE * ny, 0, 90, -20, 60));
            // the plateau straight down, looking north: rows along x, columns along z, as the face's are along z, y
            Density ground = density(engine, "ground-" + cliffs, new CameraPose(70, FACE_TOP + DISTANCE, 0, 0, -90,
                    60));
            // the rows run along a horizontal of the rock in both pictures, unstretched whatever the projection:
            // dividing by them leaves the density down the face against the plateau's, the light's scale gone
            double ratio = (face.down() / face.across()) / (ground.down() / ground.across());
            System.out.printf("cliffs=%s: face %.3f across, %.3f down; plateau %.3f, %.3f; down the face / plateau "
                    + "%.2f%n", cliffs, face.across(), face.down(), ground.across(), ground.down(), ratio);
            return ratio;
        }
    }

    static Density density(Engine engine, String name, CameraPose pose) throws IOException {
        engine.world().resource(Camera.class).setPose(pose);
        engine.update();
        engine.render();
        Image image = engine.readImage();
        image.writePng(Path.of("target/test-images/cliff-" + name + ".png"));
        // the middle half of the picture: all face, or all plateau
        int x0 = W / 4;
        int y0 = H / 4;
        double across = 0;
        double down = 0;
        double luma = 0;
        for (int y = y0; y < y0 + H / 2; y++) {
            for (int x = x0; x < x0 + W / 2; x++) {
                across += Math.abs(image.luma(x + 1, y) - image.luma(x, y));
                down += Math.abs(image.luma(x, y + 1) - image.luma(x, y));
                luma += image.luma(x, y);
            }
        }
        return new Density(across / luma, down / luma);
    }

    @Test
    void aSteepFaceShowsTheRockAsFinelyAsLevelGround() throws IOException {
        double triplanar = faceOverGround("triplanar");
        double planar = faceOverGround("planar");
        // within a factor of 2 of the level ground's density; a map projected from above stretches a 70° face by 1/cos
        // 70° ≈ 2.9, which puts it under 0.5
        assertTrue(triplanar > 0.5 && triplanar < 2, "triplanar: texel density down the 70° face over the level "
                + "plateau's " + triplanar + ", not within 2x");
        assertTrue(planar < 0.5, "projected from above the face must be stretched (the measure sees it): " + planar);
    }
}

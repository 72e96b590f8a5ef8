package org.openworld.engine.particles;

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
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.gl.Image;
import org.openworld.engine.shadow.ShadowSystem;
import org.openworld.engine.shadow.WallWorld;
import org.openworld.engine.terrain.TerrainSystem;

/**
 * Flakes in a wall's shadow ({@link WallWorld}: a sun in the east 35° up): west of the wall, up to 114 m from it at
 * the eye's height, the flakes lose the sun.
 */
@GlTest
class ParticleShadowTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    @TempDir
    static Path dir;
    static Path wall;

    @BeforeAll
    static void writeWorld() throws IOException {
        wall = WallWorld.write(dir);
    }

    /** The brightest flake seen from {@code pose}, luma 0–255. */
    static double brightestFlake(CameraPose pose) {
        Image[] images = new Image[2];
        for (int i = 0; i < 2; i++) {
            List<String> settings = new ArrayList<>(WallWorld.terrain(wall));
            settings.addAll(List.of("shadow.resolution=512", "shadow.distance=300", "system.particles=" + (i == 0),
                    "particles.count=400", "particles.size=0.2", "particles.volume=20"));
            try (Engine engine = GlTestSupport.engine(GL.context(), 320, 180, settings, new CullingSystem(),
                    new TerrainSystem(), new ShadowSystem(), new ParticleSystem())) {
                engine.world().setResource(WallWorld.EAST_SUN);
                engine.world().resource(Camera.class).setPose(pose);
                engine.update();
                engine.render();
                images[i] = engine.readImage();
            }
        }
        return Spot.find(images[0], images[1]).stream().mapToDouble(Spot::peak).max().orElseThrow();
    }

    @Test
    void flakesInTheWallsShadowLoseTheSun() {
        double sunlit = brightestFlake(new CameraPose(60, 0, 0, 90, 0, 60));    // east of the wall, looking east
        double shaded = brightestFlake(new CameraPose(-60, 0, 0, 270, 0, 60)); // in its shadow, looking west
        // 40 and 30 levels of luma, as in ParticleSystemTest: the sun's share lost in shade, the sky's kept
        assertTrue(shaded < sunlit - 40, "shaded " + shaded + " against sunlit " + sunlit);
        assertTrue(shaded > 30, "the sky still lights them: " + shaded);
    }
}

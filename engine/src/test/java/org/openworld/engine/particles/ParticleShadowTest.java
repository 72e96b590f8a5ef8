package org.openworld.engine.particles;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.joml.Vector3f;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.gl.Image;
import org.openworld.engine.shadow.ShadowSystem;
import org.openworld.engine.terrain.TerrainSystem;

/**
 * Flakes in a wall's shadow: a world of flat ground at −20 m with a wall 100 m high along x from −16 to 0 m, a sun
 * in the east 35° up. West of the wall, up to 114 m from it at the eye's height, the flakes lose the sun.
 */
class ParticleShadowTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int SAMPLES = 256;
    static final double ELEVATION = Math.toRadians(35);
    static final Sun EAST_SUN = new Sun(new Vector3f((float) Math.cos(ELEVATION), (float) Math.sin(ELEVATION), 0),
            new Vector3f(1), new Vector3f(0.25f));

    @TempDir
    static Path dir;
    static Path wall;

    @BeforeAll
    static void writeWorld() throws IOException {
        ByteBuffer bytes = ByteBuffer.allocate(4 * SAMPLES * SAMPLES).order(ByteOrder.LITTLE_ENDIAN);
        for (int z = 0; z < SAMPLES; z++) {
            for (int x = 0; x < SAMPLES; x++) {
                bytes.putFloat(x >= 120 && x < 128 ? 1f : 0f);
            }
        }
        wall = Files.write(dir.resolve("wall.raw"), bytes.array());
    }

    /** The brightest flake seen from {@code pose}, luma 0–255. */
    static double brightestFlake(CameraPose pose) {
        Image[] images = new Image[2];
        for (int i = 0; i < 2; i++) {
            try (Engine engine = GlTestSupport.engine(GL.context(), 320, 180, List.of("terrain.import-file=" + wall,
                    "terrain.spacing=2", "terrain.relief=100", "terrain.sea-fraction=0.2", "shadow.resolution=512",
                    "shadow.distance=300", "particles.enabled=" + (i == 0), "particles.count=400",
                    "particles.size=0.2", "particles.volume=20"), new CullingSystem(), new TerrainSystem(),
                    new ShadowSystem(), new ParticleSystem())) {
                engine.world().setResource(EAST_SUN);
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
        assertTrue(shaded < sunlit - 40, "shaded " + shaded + " against sunlit " + sunlit);
        assertTrue(shaded > 30, "the sky still lights them: " + shaded);
    }
}

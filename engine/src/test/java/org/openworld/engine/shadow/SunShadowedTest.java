package org.openworld.engine.shadow;

import static org.junit.jupiter.api.Assertions.assertEquals;
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
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.gl.Image;
import org.openworld.engine.terrain.TerrainSystem;

/**
 * The passes tell their systems whether the sun's shadow maps are bound ({@link RenderContext#sunShadowed}), and the
 * terrain picks its programs by it (with the lookup, or compiled without it): while the shadow system runs, MAIN is
 * shadowed and the wall's shadow shows; switched off, MAIN is not, and the ground behind the wall is lit. A terrain
 * that took the unshadowed programs while the maps are bound would lose the shadow; one that took the shadowed
 * programs without them would draw the same picture, only dearer (bench measures that).
 */
@GlTest
class SunShadowedTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    @TempDir
    static Path dir;
    static Path wall;

    @BeforeAll
    static void writeWorld() throws IOException {
        wall = WallWorld.write(dir);
    }

    /** Records what each MAIN pass was told. */
    static final class Probe implements EngineSystem {
        final List<Boolean> told = new ArrayList<>();

        @Override
        public SystemSpec spec() {
            return SystemSpec.named("probe").draws(Pass.MAIN);
        }

        @Override
        public void render(Pass pass, RenderContext context) {
            told.add(context.sunShadowed());
        }
    }

    @Test
    void mainIsShadowedExactlyWhileTheShadowSystemRuns() {
        Probe probe = new Probe();
        try (Engine engine = GlTestSupport.engine(GL.context(), ShadowRefreshTest.W, ShadowRefreshTest.H,
                settings(), new CullingSystem(), new TerrainSystem(), new ShadowSystem(), probe)) {
            engine.world().setResource(WallWorld.EAST_SUN);
            engine.world().resource(Camera.class).setPose(ShadowRefreshTest.LOW);
            Image shadowed = frame(engine);
            assertEquals(List.of(true), probe.told, "MAIN with the shadow system running");

            engine.setEnabled("shadow", false);
            Image lit = frame(engine);
            assertEquals(List.of(true, false), probe.told, "MAIN with the shadow system switched off");

            int darker = 0;
            for (int y = 0; y < ShadowRefreshTest.H; y++) {
                for (int x = 0; x < ShadowRefreshTest.W; x++) {
                    if (lit.channel(x, y, 1) - shadowed.channel(x, y, 1) > 20) {
                        darker++;
                    }
                }
            }
            assertTrue(darker > ShadowRefreshTest.W * ShadowRefreshTest.H / 20,
                    "pixels the wall's shadow darkens while the maps are bound: " + darker);
        }
    }

    private static List<String> settings() {
        List<String> s = new ArrayList<>(WallWorld.terrain(wall));
        s.addAll(List.of("shadow.resolution=256", "shadow.distance=400", "shadow.cascades=3"));
        return s;
    }

    private static Image frame(Engine engine) {
        engine.update();
        engine.render();
        return engine.readImage();
    }
}

package org.openworld.engine.terrain.material;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.Engine;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.gl.Image;
import org.openworld.engine.sky.SkySystem;

/**
 * {@code materials.specular-aa} on real GL ({@code test/terrain/glint.frag}): a polished surface where it mirrors the
 * sun, smooth on the left half, with bumps smaller than a pixel on the right (every other pixel's normal tilted by
 * 8.5 degrees). Without the anti-aliasing the bumps make a checkerboard of full glints and none, which crawls as the
 * view moves; with it each pixel's highlight is widened by the normal's spread over the pixel, so neighbours agree,
 * while the smooth half keeps its sharp glint untouched.
 */
@GlTest
class SpecularAntialiasTest {

    static final int WIDTH = 64;
    static final int HEIGHT = 32;

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    @BeforeAll
    static void synthesise() {
        MaterialRenderTest.textures = TerrainTextures.generate(EngineSettings.DEFAULTS.seed());
    }

    private static Image picture(boolean antialiased) {
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT,
                List.of("materials.specular-aa=" + (antialiased ? "on" : "off")),
                new MaterialRenderTest.MaterialPreview("test/fullscreen.vert", "test/terrain/glint.frag"),
                new SkySystem())) {
            engine.world().setResource(new TimeOfDay(MaterialRenderTest.MORNING, 0));
            engine.world().resource(Camera.class).setPose(MaterialRenderTest.ABOVE);
            engine.update();
            engine.render();
            return engine.readImage();
        }
    }

    /** Mean difference of green (0-255) between horizontal neighbours over columns x0 .. x1 - 1, rows inside. */
    private static double neighbourContrast(Image image, int x0, int x1) {
        double sum = 0;
        int pairs = 0;
        for (int y = 1; y < HEIGHT - 1; y++) {
            for (int x = x0 + 1; x < x1 - 2; x++) {
                sum += Math.abs(image.channel(x + 1, y, 1) - image.channel(x, y, 1));
                pairs++;
            }
        }
        return sum / pairs;
    }

    @Test
    void bumpsSmallerThanAPixelGiveASteadySheenNotACheckerboardOfGlints() {
        Image off = picture(false);
        Image on = picture(true);
        double crawling = neighbourContrast(off, WIDTH / 2, WIDTH);
        double steady = neighbourContrast(on, WIDTH / 2, WIDTH);
        // without: the flat texels show the whole lobe of power 2048 and the tilted ones nothing (cos 8.5 deg to the
        // 2048th power is 1e-10). With: the normal changes by about 0.15 between neighbours on both axes, a spread of
        // 0.25 (0.15^2 + 0.15^2) = 0.011, and Toksvig's lobe falls to power 2048 / (1 + 2048 * 0.011) = 86, under
        // which the tilted texels keep 0.989^86 = 39 % of the flat ones' lobe, and both lose the normalisation's
        // (2048 + 8) / (86 + 8) = 22-fold peak: neighbours must differ by well under half as much
        assertTrue(crawling > 20, "without: a checkerboard of glints, contrast " + crawling);
        assertTrue(steady < crawling / 2, "neighbours differ by " + steady + " with, " + crawling + " without");
        // the smooth half: no spread, the same sharp glint with and without (up to a level of rounding)
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 1; x < WIDTH / 2 - 1; x++) {
                assertEquals(off.channel(x, y, 1), on.channel(x, y, 1), 1, "smooth ground at " + x + "," + y);
            }
        }
    }
}

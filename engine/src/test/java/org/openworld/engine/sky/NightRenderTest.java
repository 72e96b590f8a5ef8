package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
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
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.gl.Image;
import org.openworld.engine.terrain.TerrainSystem;

/**
 * The twilight and the night as drawn: terrain seen from above, its lower half the ground only, at 17:30 (day), 19:45
 * (the sun 10° down, nautical twilight) and 23:00 (a moonless night). The ground must stay visible and read as night:
 * darker than the day by what the exposure law says, and blue. Pictures go to {@code target/test-images/}.
 */
@GlTest
class NightRenderTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int WIDTH = 160;
    static final int HEIGHT = 90;

    /** Rec. 709 luminance and the mean of each channel of the picture's lower half, 0..255 (sRGB-encoded). */
    static double[] lowerHalf(Image image) {
        double[] sum = new double[4];
        for (int y = HEIGHT / 2; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                for (int c = 0; c < 3; c++) {
                    sum[c + 1] += image.channel(x, y, c);
                }
            }
        }
        double n = WIDTH * (HEIGHT - HEIGHT / 2);
        double r = sum[1] / n, g = sum[2] / n, b = sum[3] / n;
        return new double[] {0.2126 * r + 0.7152 * g + 0.0722 * b, r, g, b};
    }

    private static Image render(Engine engine, double hours) {
        engine.world().setResource(new TimeOfDay(hours, 0));
        HeightField ground = engine.world().resource(HeightField.class);
        // 250 m over the ground, looking east and 20° down (at the slopes that face the bright western sky): the lower half (10° to 50° down) is all ground
        engine.world().resource(Camera.class).setPose(new CameraPose(0, ground.heightAt(0, 0) + 250, 0, 105, -20, 60));
        engine.update();
        engine.render();
        return engine.readImage();
    }

    @Test
    void theTwilightGroundIsDimButNotBlack() throws IOException {
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT,
                List.of("terrain.size=256", "clouds.cover=0"), new TerrainSystem(), new CullingSystem(),
                new SkySystem())) {
            Image day = render(engine, 17.5);
            Image twilight = render(engine, 19.75);
            Image night = render(engine, 23);
            day.writePng(Path.of("target/test-images/night-1730.png"));
            twilight.writePng(Path.of("target/test-images/night-1945.png"));
            night.writePng(Path.of("target/test-images/night-2300.png"));
            double[] d = lowerHalf(day);
            double[] t = lowerHalf(twilight);
            double[] n = lowerHalf(night);
            System.out.printf(Locale.ROOT, "lower half: day %.1f, twilight %.1f (rgb %.1f %.1f %.1f), night %.1f%n",
                    d[0], t[0], t[1], t[2], t[3], n[0]);

            // Not black: the night floor shows a white surface at no less than B = 0.043 of noon's (under a moonless
            // sky's airglow, darker than any twilight); a ground of albedo 0.2 (grass and rock) then shows at what
            // the display makes of 0.2 B, about 10 of 255. The law's own floor, not a run's figure:
            double floor = SkyRenderTest.display(0.2 * NightLight.SKY * Adaptation.exposure(NightLight.SKY, 0), 1);
            assertTrue(t[0] > floor, "twilight ground " + t[0] + " against the floor's " + floor);
            // Read as night: the law shows a white surface at 19:45 (ground light 5e-7) at B = 0.048 and at 17:30
            // (0.15) at 0.39, 0.125 times; on the display, through sRGB's power 1/2.4, 0.42 times; the rods see the
            // blue twilight light up to twice as bright as the cones (its V / Y), 2^(1/2.4) = 1.3 times: so the
            // twilight ground shows below 0.42 * 1.3 = 0.55 of the day's (the tone curve's toe only darkens it more).
            assertTrue(t[0] < 0.55 * d[0], "twilight against day, lower half: " + t[0] + " / " + d[0]);
            // night: the rods' blue, not the day's colours
            assertTrue(t[3] > 1.3 * t[1] && t[3] > t[2], "the twilight is blue: rgb " + t[1] + ", " + t[2] + ", " + t[3]);
            // a moonless night darker than the twilight, and not black: above 2 of 255, where before the night
            // floor every pixel was 0
            assertTrue(n[0] < t[0] && n[0] > 2, "night " + n[0] + " against twilight " + t[0]);
        }
    }
}

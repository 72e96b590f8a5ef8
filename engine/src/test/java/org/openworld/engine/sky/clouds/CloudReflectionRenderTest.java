package org.openworld.engine.sky.clouds;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.colour.ImageComparison;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.gl.Image;
import org.openworld.engine.sky.SkySystem;
import org.openworld.engine.water.WaterSystem;

/**
 * The volumetric clouds in the water's reflection, on a real GL context: looking down at the water from 10 m, the
 * reflection must show the clouds the eye sees looking up from the mirrored eye (10 m under the water, the same yaw,
 * the pitch turned up), marched whole, and not the sky's flat layer nor a clear sky.
 */
@GlTest
class CloudReflectionRenderTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    private static final int W = 160;
    private static final int H = 90;
    /** Metres above the water (at 0) of the eye; degrees down of the view (up for the mirrored one). */
    private static final double HEIGHT = 10;
    private static final double PITCH = 35;

    private static List<String> settings(String mode, double cover) {
        return new ArrayList<>(List.of("clouds.mode=" + mode, "clouds.cover=" + cover, "clouds.wind-speed=0"));
    }

    /** The water's reflection target, looking down at the water: the clouds as the mirrored camera saw them. */
    private static Image reflection(String mode, double cover) {
        WaterSystem water = new WaterSystem();
        List<String> settings = settings(mode, cover);
        settings.addAll(List.of("water.reflection=FULL", "water.level=0"));
        try (Engine engine = GlTestSupport.engine(GL.context(), W, H, settings, new SkySystem(), water,
                new CloudVolumeSystem())) {
            engine.world().setResource(new TimeOfDay(15, 0));
            engine.world().resource(Camera.class).setPose(new CameraPose(0, HEIGHT, 0, 20, -PITCH, 60));
            engine.update();
            engine.render();
            return water.reflectionTarget().read();
        }
    }

    /** The picture from the mirrored eye looking up, without water: the volume marched whole (a first frame). */
    private static Image lookingUp(double cover) {
        try (Engine engine = GlTestSupport.engine(GL.context(), W, H, settings("volumetric", cover), new SkySystem(),
                new CloudVolumeSystem())) {
            engine.world().setResource(new TimeOfDay(15, 0));
            engine.world().resource(Camera.class).setPose(new CameraPose(0, -HEIGHT, 0, 20, PITCH, 60));
            engine.update();
            engine.render();
            return engine.readImage();
        }
    }

    /** The image upside down: the mirrored camera's picture has the zenith's side at the bottom. */
    private static Image flipped(Image image) {
        byte[] rgba = new byte[image.width() * image.height() * 4];
        for (int y = 0; y < image.height(); y++) {
            for (int x = 0; x < image.width(); x++) {
                for (int c = 0; c < 4; c++) {
                    int value = c < 3 ? image.channel(x, image.height() - 1 - y, c) : 255;
                    rgba[(y * image.width() + x) * 4 + c] = (byte) value;
                }
            }
        }
        return new Image(image.width(), image.height(), rgba);
    }

    /**
     * The reflection, turned upright, against the view looking up: what the clouds change in that view (against the
     * same view under a clear sky, measured here: 11.5 at cover 0.6) must be reproduced but for a quarter of it,
     * which is what the two resamplings of the clouds' soft edges leave (the view's quarter grid is 1.5° a texel at
     * this size, the panorama 0.7° to 1.4°; measured 1.7). The sky's flat layer in the reflection (as before the
     * panorama: 12.8) and a reflection without clouds (11.5) are far outside it. Under a clear sky the reflection
     * adds nothing: within a just noticeable difference (ΔE00 1) of the clear view.
     */
    @Test
    void theWaterReflectsTheVolumetricCloudsOverhead() {
        Image up = lookingUp(0.6);
        Image clearUp = lookingUp(0);
        double cloudsMake = ImageComparison.of(up, clearUp).meanDeltaE();
        double reflected = ImageComparison.of(flipped(reflection("volumetric", 0.6)), up).meanDeltaE();
        double layer = ImageComparison.of(flipped(reflection("layer", 0.6)), up).meanDeltaE();
        double clear = ImageComparison.of(flipped(reflection("volumetric", 0)), clearUp).meanDeltaE();
        double bound = 0.25 * cloudsMake;
        assertTrue(cloudsMake > 5, "the clouds change the view looking up by a mean ΔE00 of " + cloudsMake);
        assertTrue(reflected < bound, "the reflection differs from the clouds overhead by " + reflected
                + ", above a quarter of what the clouds make, " + bound);
        assertTrue(layer > bound, "the layer's reflection passes for the volume's: " + layer);
        assertTrue(clear < 1, "without clouds the reflection differs from the clear sky by " + clear);
    }
}

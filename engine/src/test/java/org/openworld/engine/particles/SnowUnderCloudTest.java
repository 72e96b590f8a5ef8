package org.openworld.engine.particles;

import static org.junit.jupiter.api.Assertions.assertEquals;
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
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.gl.Image;
import org.openworld.engine.sky.SkySystem;
import org.openworld.engine.sky.clouds.CloudVolumeSystem;

/**
 * Snow falls from the cloud above it: with the volumetric clouds, flakes under an overcast and none under a clear
 * sky; with the flat layer, which has no depth to tell, the snowfall as set. The eye looks down (below the horizon,
 * where the clouds draw nothing) at a few big flakes, counted as the spots a frame gains with them. Without the
 * snowfall's share from the cloud overhead the clear sky shows as many flakes as the layer.
 */
@GlTest
class SnowUnderCloudTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    /**
     * The flakes a frame shows: spots against the same frame without snow, brighter or darker (under an overcast the
     * flakes lose the sun and stand darker than the grey below the horizon).
     */
    static int flakes(String... clouds) {
        Image[] images = new Image[2];
        for (int i = 0; i < 2; i++) {
            List<String> settings = new ArrayList<>(List.of("system.particles=" + (i == 0), "particles.count=400",
                    "particles.size=0.2", "particles.volume=20", "clouds.wind-speed=0"));
            settings.addAll(List.of(clouds));
            try (Engine engine = GlTestSupport.engine(GL.context(), ParticleSystemTest.W, ParticleSystemTest.H,
                    settings, new SkySystem(), new CloudVolumeSystem(), new ParticleSystem())) {
                engine.world().setResource(new TimeOfDay(12, 0));
                engine.world().resource(Camera.class).setPose(new CameraPose(0, 20, 0, 0, -60, 60));
                engine.update();
                engine.render();
                images[i] = engine.readImage();
            }
        }
        return Spot.find(images[0], images[1]).size() + Spot.find(images[1], images[0]).size();
    }

    @Test
    void snowFallsUnderAnOvercastAndNotUnderAClearSky() {
        // an overcast: every cloud.cover; a stratus sheet (type 0) 1 500 m thick, an optical depth of tens overhead
        int overcast = flakes("clouds.mode=volumetric", "clouds.cover=1", "clouds.type=0");
        // the same count of flakes the snowfall draws without clouds to tell it where (ParticleSystemTest's scene)
        int layer = flakes("clouds.mode=layer", "clouds.cover=0");
        int clear = flakes("clouds.mode=volumetric", "clouds.cover=0");
        // ten flakes at least, as ParticleSystemTest counts them in this scene
        assertTrue(overcast >= 10, overcast + " flakes under an overcast");
        assertTrue(layer >= 10, layer + " flakes with the flat layer");
        assertEquals(0, clear, "flakes under a clear sky");
    }
}

package org.openworld.engine.particles;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.Engine;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.environment.Wind;
import org.openworld.engine.gl.GlObjects;
import org.openworld.engine.gl.Image;

/** The snow on real GL: the transform feedback against the CPU reference, the cube, the ground, the picture. */
@GlTest
class ParticleSystemTest {

    static final int W = 320;
    static final int H = 180;
    /** A slope through the cube around the eye (y 5 to 35 for the 30 m cube at y 20): flakes land on it. */
    static final HeightField SLOPE = (x, z) -> 10 + 0.3 * x + 0.5 * Math.sin(0.2 * z);
    static final HeightField DEEP = (x, z) -> -1000;

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    final ParticleSystem snow = new ParticleSystem();

    Engine engine(HeightField ground, String... settings) {
        List<String> all = new ArrayList<>(List.of("system.particles=on"));
        all.addAll(List.of(settings));
        Engine engine = GlTestSupport.engine(GL.context(), W, H, all, snow);
        engine.world().setResource(HeightField.class, ground);
        engine.world().resource(Camera.class).setPose(new CameraPose(0, 20, 0, 0, 0, 60));
        return engine;
    }

    static CameraPose pose(Engine engine) {
        return engine.world().resource(Camera.class).pose();
    }

    @Test
    void theTransformFeedbackStepsMatchTheCpuReferenceWhileTheEyeMovesAndFlakesLand() {
        try (Engine engine = engine(SLOPE, "particles.count=5000", "particles.turbulence=0", "particles.volume=30",
                "particles.drag=1.5", "particles.fall-speed=1.2")) {
            engine.world().setResource(new Wind(new Vector3f(4, 0, -3)));
            engine.render(); // builds the buffers and spreads a fresh fall
            float[] cpu = snow.readState();
            ParticleSettings s = engine.settings().get(ParticleSettings.class);
            EngineSettings e = engine.settings().get(EngineSettings.class);
            SnowMotion.Forces forces = new SnowMotion.Forces((float) s.gravity(), (float) s.drag(), 0,
                    new Vector3f(4, 0, -3).mul((float) s.windShare()), (float) e.step());
            int landed = 0;
            int wrapped = 0;
            for (int n = 0; n < 60; n++) {
                CameraPose p = pose(engine);
                // the eye runs east at 30 m/s: flakes wrap round the west face, the ground patch is sampled again
                engine.world().resource(Camera.class).setPose(new CameraPose(p.x() + 0.5, 20, p.z(), 0, 0, 60));
                engine.update();
                float[] before = cpu.clone();
                SnowMotion.step(cpu, forces, new SnowMotion.Volume(new Vector3f((float) p.x() + 0.5f, 20, 0), 30),
                        snow.ground(), SnowMotion.stepKey(e.seed(), n));
                for (int i = 0; i < cpu.length; i += SnowMotion.FLOATS) {
                    landed += cpu[i + 1] > before[i + 1] + 5 ? 1 : 0;
                    wrapped += cpu[i] > before[i] + 5 ? 1 : 0;
                }
            }
            // over 100 of each: both rare paths (landing, wrapping) are compared many times, not once or twice
            assertTrue(landed > 100 && wrapped > 100, "the run must exercise both: " + landed + " landed, "
                    + wrapped + " wrapped");
            float[] gpu = snow.readState();
            int apart = 0;
            double worst = 0;
            for (int i = 0; i < cpu.length; i++) {
                double d = Math.abs(gpu[i] - cpu[i]);
                if (d > 1e-3) {
                    apart++; // a flake exactly on a face can wrap on one side and not the other (division rounding)
                } else {
                    worst = Math.max(worst, d);
                }
            }
            assertTrue(apart <= cpu.length / 1000, apart + " of " + cpu.length + " values differ");
            // GPU and CPU both step in float (24-bit mantissa); positions of tens of metres round at ~4e-6 m a step, so
            // 1e-3 m holds many steps' drift apart
            assertTrue(worst < 1e-3, "largest difference " + worst);
        }
    }

    @Test
    void flakesStayInTheCubeAroundTheEyeAndAboveTheGround() {
        try (Engine engine = engine(SLOPE, "particles.count=20000", "particles.turbulence=2",
                "particles.volume=30")) {
            engine.world().setResource(new Wind(new Vector3f(25, 0, 10)));
            for (int n = 0; n < 90; n++) {
                CameraPose p = pose(engine);
                engine.world().resource(Camera.class).setPose(new CameraPose(p.x() - 0.8, 20 + 0.1 * n, p.z() + 0.4,
                        0, 0, 60));
                engine.update();
            }
            CameraPose eye = pose(engine);
            float[] state = snow.readState();
            for (int i = 0; i < state.length; i += SnowMotion.FLOATS) {
                // half the 30 m cube, plus 1 mm for float positions (24-bit mantissa, ~2e-6 m at tens of metres); the
                // ground by 1 cm likewise
                assertTrue(Math.abs(state[i] - eye.x()) <= 15.001 && Math.abs(state[i + 1] - eye.y()) <= 15.001
                        && Math.abs(state[i + 2] - eye.z()) <= 15.001, "flake " + i / SnowMotion.FLOATS
                        + " left the cube");
                assertTrue(state[i + 1] >= SLOPE.heightAt(state[i], state[i + 2]) - 0.01,
                        "flake " + i / SnowMotion.FLOATS + " under the ground");
            }
        }
    }

    @Test
    void anEyeThatJumpsOrANewCubeSizeGetsAFreshFallWithoutNewBuffers() {
        try (Engine engine = engine(SLOPE, "particles.count=5000", "particles.volume=30")) {
            engine.update();
            // a cut: 2 km east, where the slope is 600 m up (a shot sets its pose after the first step like this)
            engine.world().resource(Camera.class).setPose(new CameraPose(2000, 620, 0, 0, 0, 60));
            engine.render();
            assertEquals(1, snow.builds(), "the buffers are kept");
            float[] state = snow.readState();
            for (int i = 0; i < state.length; i += SnowMotion.FLOATS) {
                // the cube's half-side (15 m, then 5 m after the resize): every flake respawned inside it
                assertTrue(Math.abs(state[i] - 2000) <= 15 && Math.abs(state[i + 1] - 620) <= 15,
                        "around the new eye");
                assertTrue(state[i + 1] >= SLOPE.heightAt(state[i], state[i + 2]) - 0.01, "in its air");
            }
            engine.settings().set("particles.volume", "10");
            engine.render();
            state = snow.readState();
            for (int i = 0; i < state.length; i += SnowMotion.FLOATS) {
                assertTrue(Math.abs(state[i] - 2000) <= 5 && Math.abs(state[i + 2]) <= 5, "spread through the new cube");
            }
            assertEquals(1, snow.builds(), "still the same buffers");
        }
    }

    @Test
    void theBrownianMotionOnTheGpuSpreadsTheVelocityAsTheAnalysisSays() {
        try (Engine engine = engine(DEEP, "particles.count=20000", "particles.turbulence=0.5",
                "particles.drag=2")) {
            int steps = 300; // ten time constants of 1/k = 0.5 s at 60 steps a second
            for (int n = 0; n < steps; n++) {
                engine.update();
            }
            ParticleSettings s = engine.settings().get(ParticleSettings.class);
            double settled = SnowMotion.settledVariance(s.brownian(), s.drag(),
                    engine.settings().get(EngineSettings.class).step());
            float[] state = snow.readState();
            for (int axis = 0; axis < 3; axis++) {
                double mean = axis == 1 ? -s.fallSpeed() : 0;
                double sum = 0;
                for (int i = 0; i < state.length; i += SnowMotion.FLOATS) {
                    double d = state[i + 3 + axis] - mean;
                    sum += d * d;
                }
                assertEquals(settled, sum / s.count(), 0.05 * settled, "axis " + axis);
            }
        }
    }

    /** A frame with a few big flakes against the black of an empty world, and the same frame without them. */
    static Image[] withAndWithout(Sun sun) {
        return withAndWithout(sun, 0.2);
    }

    static Image[] withAndWithout(Sun sun, double size) {
        Image[] images = new Image[2];
        for (int i = 0; i < 2; i++) {
            try (Engine engine = GlTestSupport.engine(GL.context(), W, H, List.of("system.particles=" + (i == 0),
                    "particles.count=400", "particles.size=" + size, "particles.volume=20"), new ParticleSystem())) {
                engine.world().setResource(sun);
                engine.world().resource(Camera.class).setPose(new CameraPose(0, 20, 0, 0, 0, 60));
                engine.update();
                engine.render();
                images[i] = engine.readImage();
            }
        }
        return images;
    }

    @Test
    void snowAddsSmallRoundBrightSpotsWithSoftRimsFainterWithDistance() {
        Image[] images = withAndWithout(Sun.NOON);
        List<Spot> spots = Spot.find(images[0], images[1]);
        // spot counts chosen to have a few of each kind to judge (10 spots, 3 near and 3 far); a flake covers under 1 %
        // of the picture
        assertTrue(spots.size() >= 10, spots.size() + " spots");
        List<Spot> near = new ArrayList<>();
        List<Spot> far = new ArrayList<>();
        for (Spot spot : spots) {
            assertTrue(spot.pixels() < W * H / 100, "a flake is small: " + spot);
            if (spot.width() >= 7 && !spot.touchesEdge(W, H)) {
                near.add(spot);
            } else if (spot.width() <= 3) {
                far.add(spot);
            }
        }
        assertTrue(near.size() >= 3 && far.size() >= 3, near.size() + " near flakes, " + far.size() + " far");
        for (Spot spot : near) {
            // luma 150 of 255: a sunlit white flake is near white; a rim under 60 % of the peak is a visible falloff;
            // 25 % on the aspect covers odd pixel counts of a small disc (7 px: 7/6 = 1.17)
            assertTrue(spot.peak() > 150, "bright: " + spot);
            // a disc fills pi/4 = 0.79 of its bounding square, a square billboard all of it
            assertEquals(Math.PI / 4, spot.fill(), 0.12, "round: " + spot);
            assertEquals(1, (double) spot.width() / spot.height(), 0.25, "as tall as wide: " + spot);
            assertTrue(spot.rim() < 0.6 * spot.peak(), "a soft rim, darker than the core: " + spot);
        }
        // under a pixel's size a flake stays a pixel big and gives the light it would cover: it fades
        double nearPeak = near.stream().mapToDouble(Spot::peak).average().orElseThrow();
        double farPeak = far.stream().mapToDouble(Spot::peak).average().orElseThrow();
        // a flake under a pixel covers a share of it: far ones must be plainly fainter, 30 % or more; the same 150
        // bounds the brightest pixel-sized flake
        assertTrue(farPeak < 0.7 * nearPeak, "far flakes fainter: " + farPeak + " against " + nearPeak);
    }

    @Test
    void flakesSmallerThanAPixelAreDrawnAPixelBigAndFadedByTheirShareOfIt() {
        // 3 cm flakes: under a pixel's radius beyond 2.3 m in this 320 x 180 picture
        Image[] images = withAndWithout(Sun.NOON, 0.03);
        List<Spot> pixelSized = Spot.find(images[0], images[1]).stream()
                .filter(spot -> spot.width() <= 3 && spot.height() <= 3).toList();
        assertTrue(pixelSized.size() >= 10, "still seen, not lost between pixel centres: " + pixelSized.size());
        double brightest = pixelSized.stream().mapToDouble(Spot::peak).max().orElseThrow();
        assertTrue(brightest < 150, "faded by the share of the pixel they would cover: " + brightest);
    }

    @Test
    void theFlakesAreLitByTheSunAndTheSky() {
        Sun noon = Sun.NOON;
        Sun skyOnly = new Sun(noon.direction(), new Vector3f(0), noon.ambient());
        Image[] lit = withAndWithout(noon);
        double sunlit = Spot.find(lit[0], lit[1]).stream().mapToDouble(Spot::peak).max().orElseThrow();
        Image[] shaded = withAndWithout(skyOnly);
        double bySky = Spot.find(shaded[0], shaded[1]).stream().mapToDouble(Spot::peak).max().orElseThrow();
        // 30 levels: clearly above the dark background; the sun adds 40 more, the share of direct light at noon
        assertTrue(bySky > 30, "the sky alone lights them: " + bySky);
        assertTrue(sunlit > bySky + 40, "the sun adds its share: " + sunlit + " against " + bySky);
    }

    @Test
    void changingTheCountRebuildsTheBuffersOnceAndNothingIsBuiltWhileItDoesNotSnow() {
        try (Engine engine = engine(DEEP, "system.particles=off", "particles.count=1000")) {
            engine.update();
            engine.render();
            assertEquals(0, snow.builds(), "no snow, no buffers");
            int buffers = GL.context().objects().live(GlObjects.Kind.BUFFER);
            engine.settings().set("system.particles", "on");
            engine.update();
            engine.render();
            assertEquals(1, snow.builds());
            assertEquals(buffers + 2, GL.context().objects().live(GlObjects.Kind.BUFFER), "two state buffers");
            engine.settings().set("particles.count", "3000");
            for (int n = 0; n < 3; n++) {
                engine.update();
                engine.render();
            }
            assertEquals(2, snow.builds(), "rebuilt once for the new count, not every frame");
            assertEquals(3000 * SnowMotion.FLOATS, snow.readState().length);
            assertEquals(buffers + 2, GL.context().objects().live(GlObjects.Kind.BUFFER), "the old ones deleted");
        }
        assertEquals(0, GL.context().objects().live(), "every GL object returned: " + GL.context().objects());
    }
}

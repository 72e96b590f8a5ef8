package org.openworld.engine.terrain.stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL30C.GL_RG;
import static org.lwjgl.opengl.GL30C.GL_TEXTURE_2D_ARRAY;
import static org.lwjgl.opengl.GL30C.GL_UNSIGNED_BYTE;
import static org.lwjgl.opengl.GL30C.glGetTexImage;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.gl.Image;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.terrain.StreamedGround;
import org.openworld.engine.terrain.TerrainSystem;
import org.openworld.engine.terrain.heights.BandedHeights;
import org.openworld.engine.terrain.material.HorizonSearch;
import org.openworld.engine.terrain.material.SkyVisibility;
import org.openworld.engine.water.WaterSystem;

/**
 * The unbounded world's share of the sky seen ({@link StreamedSky}), read back from the g channel of the snow map's
 * layers once every block has had its pass, against {@link SkyVisibility}'s formula evaluated on the CPU from
 * {@link BandedHeights} itself: the same azimuths, distances and level choice, with the heights computed where the
 * pass reads them from the clipmap's textures.
 */
@GlTest
class StreamedSkyTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    /** Levels whose texels are checked. */
    static final int[] LEVELS = {0, 1, 3, 5};
    /** Texels checked per level, at random. */
    static final int POINTS = 100;
    /**
     * The largest difference allowed at a point: the byte's rounding (1/510), the slopes stored as half floats and
     * the heights as floats, with margin (measured: 0.0020 at worst, 0.0009 on average).
     */
    static final double TOLERANCE = 0.01;
    /** The mean difference allowed over all points. */
    static final double MEAN_TOLERANCE = 0.002;

    /**
     * 400 texels of levels 0, 1, 3 and 5 around the camera, each within 200 · 2^L m of it, so that every level the
     * search reads holds what it reaches (the camera lies a quarter window inside each): the pass's V is the CPU's
     * within {@value #TOLERANCE} at each and {@value #MEAN_TOLERANCE} on average, the places span hollows
     * (V &lt; 0.8) and open ground (V &gt; 0.97), and the snow in the r channel is still there. With the pass
     * broken (V = 1 everywhere, as before it, or read from the wrong level, place or distance) the hollows differ by
     * more than 0.2; with the colour mask lost the snow is gone.
     */
    @Test
    void theSkySeenMatchesTheTilesFormulaOnTheWorldsHeights() {
        TerrainSystem terrain = new TerrainSystem();
        try (Engine engine = GlTestSupport.engine(GL.context(), 64, 36, List.of("terrain.world=unbounded"),
                terrain)) {
            BandedHeights world = (BandedHeights) engine.world().resource(HeightField.class);
            double cx = 700;
            double cz = -300;
            engine.world().resource(Camera.class).setPose(new CameraPose(cx, world.heightAt(cx, cz) + 300, cz, 0,
                    -30, 60));
            engine.update();
            engine.render();
            UnboundedWorld unbounded = ((StreamedGround) terrain.ground()).world();
            unbounded.settleSky();
            assertEquals(0, unbounded.skyWaiting(), "blocks still waiting for their pass");

            int size = unbounded.stream().clipSize();
            int levels = unbounded.stream().levels();
            ByteBuffer texels = MemoryUtil.memAlloc(2 * size * size * levels);
            try {
                unbounded.snowTexture.bind(0);
                glGetTexImage(GL_TEXTURE_2D_ARRAY, 0, GL_RG, GL_UNSIGNED_BYTE, texels);
                Random random = new Random(20);
                double worst = 0;
                double sum = 0;
                double lowest = 1;
                double highest = 0;
                int snowy = 0;
                int n = 0;
                List<String> far = new ArrayList<>();
                for (int level : LEVELS) {
                    double d = world.spacing(level);
                    double reach = 200 * Math.scalb(1.0, level);
                    for (int i = 0; i < POINTS; i++) {
                        long ix = Math.round((cx + reach * (2 * random.nextDouble() - 1)) / d);
                        long iz = Math.round((cz + reach * (2 * random.nextDouble() - 1)) / d);
                        int at = 2 * (int) ((level * (long) size + (iz & (size - 1))) * size + (ix & (size - 1)));
                        double gpu = (texels.get(at + 1) & 0xFF) / 255.0;
                        double cpu = reference(world, levels, level, ix, iz);
                        double error = Math.abs(gpu - cpu);
                        if (error > TOLERANCE) {
                            far.add(String.format(Locale.ROOT, "level %d sample (%d, %d): V = %.3f on the GPU, "
                                    + "%.3f on the CPU", level, ix, iz, gpu, cpu));
                        }
                        worst = Math.max(worst, error);
                        sum += error;
                        lowest = Math.min(lowest, gpu);
                        highest = Math.max(highest, gpu);
                        snowy += texels.get(at) != 0 ? 1 : 0;
                        n++;
                    }
                }
                String seen = String.format(Locale.ROOT, "%d points: mean |ΔV| %.4f, worst %.4f, V from %.3f to "
                        + "%.3f, %d with snow", n, sum / n, worst, lowest, highest, snowy);
                System.out.println(seen);
                assertTrue(far.isEmpty(), far.size() + " places beyond " + TOLERANCE + ": " + far + "; " + seen);
                assertTrue(sum / n <= MEAN_TOLERANCE, seen);
                // the sampled places must span the range the tolerance is about: some under 0.8 of the sky (a hollow),
                // some over 0.97 (near-open ground, within the 8-bit storage's steps of 1)
                assertTrue(lowest < 0.8, "a hollow among the places: " + seen);
                assertTrue(highest > 0.97, "open ground among the places: " + seen);
                assertTrue(snowy > 0, "the snow in r survives the pass: " + seen);
            } finally {
                MemoryUtil.memFree(texels);
            }
        }
    }

    /**
     * The first frame shades only the blocks its passes draw, and draws none before its pass: the frame is the same,
     * pixel for pixel, when drawn again, unmoved, once every block has had its pass. The view takes in a lake, so
     * that the water's reflection draws ground too (OffscreenStateTest checks that a block's pass inside it is not
     * cut short by its scissor and clip plane). With the passes not shading what they draw, the ground would show
     * the whole sky (V = 1) until the blocks' turn came, a few a step.
     */
    @Test
    void theFirstFrameShadesWhatItDrawsAndNoMore() throws IOException {
        TerrainSystem terrain = new TerrainSystem();
        try (Engine engine = GlTestSupport.engine(GL.context(), 160, 90, List.of("terrain.world=unbounded"),
                new CullingSystem(), terrain, new WaterSystem())) {
            BandedHeights world = (BandedHeights) engine.world().resource(HeightField.class);
            CameraPose pose = new CameraPose(700, world.heightAt(700, -300) + 300, -300, 0, -30, 60);
            // a lake 40 m deep where the view meets the ground, 520 m ahead
            engine.world().resource(Settings.class).set("water.level",
                    Double.toString(world.heightAt(700, -300 - 520) + 40));
            engine.world().resource(Camera.class).setPose(pose);
            engine.update();
            engine.render();
            Image first = engine.readImage();
            double[] mirrored = new double[1];
            engine.collectFrames(true, f -> mirrored[0] = f.counters().getOrDefault("terrain.reflection.patches", 0.0));
            assertTrue(mirrored[0] > 0, "the reflection draws ground");
            UnboundedWorld unbounded = ((StreamedGround) terrain.ground()).world();
            int waiting = unbounded.skyWaiting();
            int slots = unbounded.stream().clipSize() / StreamedWorld.BLOCK;
            int blocks = unbounded.stream().levels() * slots * slots;
            engine.render(); // one frame's budget of the rest, the simulation's time standing still
            assertTrue(unbounded.skyWaiting() < waiting, "the next frame shades some of the rest");
            unbounded.settleSky(); // and the rest, a frame's budget at a time
            engine.render();
            assertEquals(0, unbounded.skyWaiting(), "blocks still waiting for their pass");
            Image again = engine.readImage();
            first.writePng(Path.of("target/test-images/unbounded-sky-first.png"));
            int differ = 0;
            for (int y = 0; y < 90; y++) {
                for (int x = 0; x < 160; x++) {
                    for (int c = 0; c < 3; c++) {
                        if (first.channel(x, y, c) != again.channel(x, y, c)) {
                            differ++;
                            break;
                        }
                    }
                }
            }
            assertEquals(0, differ, "pixels that differ once every block has had its pass");
            assertTrue(waiting > blocks / 2, waiting + " of " + blocks + " blocks left after the first frame");
        }
    }

    /**
     * {@link SkyVisibility}'s V at level {@code level}'s sample (ix, iz): the horizon along each azimuth over its
     * distances, each read bilinearly from the level {@link HorizonSearch#levelAt} picks, its rise over the tangent
     * plane of the central differences, {@code (1/N) Σ cos² α}.
     */
    static double reference(BandedHeights world, int levels, int level, long ix, long iz) {
        double d = world.spacing(level);
        double x = ix * d;
        double z = iz * d;
        double h0 = world.height(level, x, z);
        double gx = (world.height(level, x + d, z) - world.height(level, x - d, z)) / (2 * d);
        double gz = (world.height(level, x, z + d) - world.height(level, x, z - d)) / (2 * d);
        double[] distances = HorizonSearch.distances(d);
        double sum = 0;
        for (int m = 0; m < HorizonSearch.DIRECTIONS; m++) {
            double cos = Math.cos(2 * Math.PI * m / HorizonSearch.DIRECTIONS);
            double sin = Math.sin(2 * Math.PI * m / HorizonSearch.DIRECTIONS);
            double horizon = Double.NEGATIVE_INFINITY;
            for (double r : distances) {
                int k = HorizonSearch.levelAt(r, level, levels, world::spacing);
                horizon = Math.max(horizon, (bilinear(world, k, x + r * cos, z + r * sin) - h0) / r);
            }
            sum += SkyVisibility.visibleShare(horizon, gx * cos + gz * sin);
        }
        return sum / HorizonSearch.DIRECTIONS;
    }

    /** Level k's height at (x, z) metres, bilinear between its four samples around. */
    private static double bilinear(BandedHeights world, int k, double x, double z) {
        double dk = world.spacing(k);
        double x0 = Math.floor(x / dk);
        double z0 = Math.floor(z / dk);
        double fx = x / dk - x0;
        double fz = z / dk - z0;
        double top = world.height(k, x0 * dk, z0 * dk) * (1 - fx) + world.height(k, (x0 + 1) * dk, z0 * dk) * fx;
        double bottom = world.height(k, x0 * dk, (z0 + 1) * dk) * (1 - fx)
                + world.height(k, (x0 + 1) * dk, (z0 + 1) * dk) * fx;
        return top * (1 - fz) + bottom * fz;
    }
}

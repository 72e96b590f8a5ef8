package org.openworld.engine.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.bench.FrameRecord;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.colour.DeltaE;
import org.openworld.engine.colour.Lab;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.gl.Image;
import org.openworld.engine.sky.SkySystem;
import org.openworld.engine.terrain.heights.TerrainSettings;

/**
 * The far material against the near one it stands in for: the same ground drawn all near
 * ({@code materials.far-texels} beyond everything) and all far ({@code 0}) must agree in its mean colour over every
 * block of the picture, since where the two meet the near program fades into the far one. A far material that lost
 * a layer, the macro tint, the snow or its place on the map would shift whole blocks. On the tile the far program
 * reads the bake; on the unbounded world it samples the materials at the coarse scale alone. Pictures go to
 * {@code target/test-images/far-material-*.png}.
 */
@GlTest
class FarMaterialRenderTest {

    static final int WIDTH = 320;
    static final int HEIGHT = 180;
    /** Blocks of the picture whose mean colours are compared: 16 × 9 of 20 × 20 pixels. */
    static final int BLOCK = 20;

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    void theFarMaterialShowsTheNearOnesMeanColourOverEveryBlock(TerrainSettings.World world) throws IOException {
        // a 1 km tile (or the unbounded world) with snow on its heights, seen from above: grass, rock and snow at
        // 150 to 700 m
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT,
                List.of("terrain.size=512", "terrain.spacing=2", "terrain.relief=400", "terrain.world=" + world),
                new TerrainSystem(), new CullingSystem())) {
            engine.world().setResource(new TimeOfDay(11.0, 0));
            engine.world().resource(Camera.class).setPose(new CameraPose(0, 450, 350, 0, -35, 60));
            engine.settings().set("materials.far-texels", "100000");
            String name = world.toString().toLowerCase(Locale.ROOT);
            Image near = frame(engine, name + "-near");
            Map<String, Double> counters = lastCounters(engine);
            assertEquals(counters.get("terrain.main.patches"), counters.get("terrain.main.near"), "all near");
            engine.settings().set("materials.far-texels", "0");
            Image far = frame(engine, name + "-far");
            assertEquals(0, lastCounters(engine).get("terrain.main.near"), "all far");

            double sum = 0;
            double worst = 0;
            int blocks = 0;
            for (int by = 0; by < HEIGHT / BLOCK; by++) {
                for (int bx = 0; bx < WIDTH / BLOCK; bx++) {
                    Lab a = blockMean(near, bx, by);
                    Lab b = blockMean(far, bx, by);
                    if (a == null || b == null) {
                        continue; // background in either picture: not ground
                    }
                    double d = DeltaE.ciede2000(a, b);
                    sum += d;
                    worst = Math.max(worst, d);
                    blocks++;
                }
            }
            // ΔE00 ≈ 1 is a just-noticeable difference between flat patches, 2–3 between textured ones: a mean of 2.5
            // over the block means is at the edge of notice; 8 bounds the worst block, where the far mip's average and
            // the near texels differ most (a band chosen, not a measured value with its noise)
            assertTrue(blocks > 100, "the view shows ground in most blocks: " + blocks);
            assertTrue(sum / blocks < 2.5, "mean ΔE00 of the block means, far against near: " + sum / blocks);
            assertTrue(worst < 8, "largest ΔE00 of a block mean, far against near: " + worst);
        }
    }

    /** The far material is baked again when the snow rule changes while running: the far ground shows the bands. */
    @Test
    void changingTheSnowRuleBakesTheFarMaterialAgain() throws IOException {
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT,
                List.of("terrain.size=512", "terrain.spacing=2", "terrain.relief=400", "materials.far-texels=0"),
                new TerrainSystem(), new CullingSystem())) {
            engine.world().setResource(new TimeOfDay(11.0, 0));
            engine.world().resource(Camera.class).setPose(new CameraPose(0, 450, 350, 0, -35, 60));
            Image map = frame(engine, "snow-map");
            engine.settings().set("materials.snow-mode", "altitude-bands");
            Image bands = frame(engine, "altitude-bands");

            double sum = 0;
            int blocks = 0;
            for (int by = 0; by < HEIGHT / BLOCK; by++) {
                for (int bx = 0; bx < WIDTH / BLOCK; bx++) {
                    Lab a = blockMean(map, bx, by);
                    Lab b = blockMean(bands, bx, by);
                    if (a != null && b != null) {
                        sum += DeltaE.ciede2000(a, b);
                        blocks++;
                    }
                }
            }
            // a difference that must show: above the 2.5 agreement band the far/near test accepts
            assertTrue(sum / blocks > 3, "mean ΔE00 of the block means, bands against the snow map: " + sum / blocks);
        }
    }

    /**
     * The far material is baked again when the tiling changes, and stochastic tiling keeps the ground's colour: the
     * pixels differ (the shifted patches are baked in) while the block means stay within the far-near tolerance,
     * since the variance-preserving blend pivots on each texture's mean.
     */
    @Test
    void changingTheTilingBakesTheFarMaterialAgainInTheSameColours() throws IOException {
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT,
                List.of("terrain.size=512", "terrain.spacing=2", "terrain.relief=400", "materials.far-texels=0"),
                new TerrainSystem(), new CullingSystem())) {
            engine.world().setResource(new TimeOfDay(11.0, 0));
            engine.world().resource(Camera.class).setPose(new CameraPose(0, 450, 350, 0, -35, 60));
            Image repeat = frame(engine, "repeat");
            engine.settings().set("materials.tiling", "stochastic");
            Image stochastic = frame(engine, "stochastic");

            double pixels = 0;
            int ground = 0;
            for (int y = 0; y < HEIGHT; y++) {
                for (int x = 0; x < WIDTH; x++) {
                    if (repeat.channel(x, y, 0) + repeat.channel(x, y, 1) + repeat.channel(x, y, 2) > 0) {
                        pixels += DeltaE.ciede2000(lab(repeat, x, y), lab(stochastic, x, y));
                        ground++;
                    }
                }
            }
            double sum = 0;
            int blocks = 0;
            for (int by = 0; by < HEIGHT / BLOCK; by++) {
                for (int bx = 0; bx < WIDTH / BLOCK; bx++) {
                    Lab a = blockMean(repeat, bx, by);
                    Lab b = blockMean(stochastic, bx, by);
                    if (a != null && b != null) {
                        sum += DeltaE.ciede2000(a, b);
                        blocks++;
                    }
                }
            }
            // per pixel the tilings differ (above a JND of 1), yet their block means agree within the same 2.5 as far
            // against near
            assertTrue(pixels / ground > 1, "mean ΔE00 per pixel, stochastic against repeat: " + pixels / ground);
            assertTrue(sum / blocks < 2.5, "mean ΔE00 of the block means, stochastic against repeat: " + sum / blocks);
        }
    }

    private static Lab lab(Image image, int x, int y) {
        return Lab.fromSrgb(image.channel(x, y, 0), image.channel(x, y, 1), image.channel(x, y, 2));
    }

    /**
     * The far ground mirrors the sky as the near ground does: what the gloss maps add (the sun's highlight and the
     * sky's reflection) agrees between the two. The far program reads the sky per vertex at two levels of blur and
     * the near one per pixel at the gloss's own level, so their sums differ a little, but a far ground that lost the
     * sky, or read it along another direction, would add far less at this low sun, seen across the slopes.
     */
    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    void theFarGroundMirrorsTheSkyAsTheNearOneDoes(TerrainSettings.World world) throws IOException {
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT,
                List.of("terrain.size=512", "terrain.spacing=2", "terrain.relief=400", "terrain.world=" + world),
                new TerrainSystem(), new CullingSystem(), new SkySystem())) {
            engine.world().setResource(new TimeOfDay(17.5, 0));
            engine.world().resource(Camera.class).setPose(new CameraPose(0, 600, 400, 0, -15, 60));
            engine.settings().set("materials.far-texels", "100000");
            String name = world.toString().toLowerCase(Locale.ROOT);
            double near = glossGain(engine, name + "-near");
            engine.settings().set("materials.far-texels", "0");
            double far = glossGain(engine, name + "-far");
            // 0.5 L*: half a just-noticeable lightness step, enough to show the gloss adds light; far and near agree
            // within 20 % (the Javadoc's per-vertex against per-pixel sky reads)
            assertTrue(near > 0.5, "the gloss maps add lightness (L*) to the near ground: " + near);
            assertTrue(Math.abs(far - near) < 0.2 * near, "light the gloss maps add, far " + far + " against near "
                    + near);
        }
    }

    /** Mean CIE lightness L* of the picture's lower two thirds (ground) with the gloss maps less without them. */
    private static double glossGain(Engine engine, String name) throws IOException {
        engine.settings().set("materials.gloss-map", "off");
        double off = meanLightness(frame(engine, name + "-matte"));
        engine.settings().set("materials.gloss-map", "on");
        return meanLightness(frame(engine, name + "-gloss")) - off;
    }

    private static double meanLightness(Image image) {
        double sum = 0;
        for (int y = HEIGHT / 3; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                sum += Lab.fromSrgb(image.channel(x, y, 0), image.channel(x, y, 1), image.channel(x, y, 2)).l();
            }
        }
        return sum / ((HEIGHT - HEIGHT / 3) * WIDTH);
    }

    /** The mean colour of a block as Lab, or null if any pixel of it is the black background. */
    private static Lab blockMean(Image image, int bx, int by) {
        long r = 0, g = 0, b = 0;
        for (int y = by * BLOCK; y < (by + 1) * BLOCK; y++) {
            for (int x = bx * BLOCK; x < (bx + 1) * BLOCK; x++) {
                int pr = image.channel(x, y, 0), pg = image.channel(x, y, 1), pb = image.channel(x, y, 2);
                if (pr + pg + pb == 0) {
                    return null;
                }
                r += pr;
                g += pg;
                b += pb;
            }
        }
        int n = BLOCK * BLOCK;
        return Lab.fromSrgb((int) Math.round((double) r / n), (int) Math.round((double) g / n),
                (int) Math.round((double) b / n));
    }

    /** The counters of the last frame rendered. */
    private static Map<String, Double> lastCounters(Engine engine) {
        List<FrameRecord> frames = new ArrayList<>();
        engine.collectFrames(true, frames::add);
        return frames.get(frames.size() - 1).counters();
    }

    private static Image frame(Engine engine, String name) throws IOException {
        engine.update();
        engine.render();
        Image image = engine.readImage();
        image.writePng(Path.of("target/test-images/far-material-" + name + ".png"));
        return image;
    }
}

package org.openworld.engine.water;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.joml.Matrix4f;
import org.joml.Vector4f;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.ImportedWorld;
import org.openworld.engine.bench.FrameRecord;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.gl.Image;
import org.openworld.engine.sky.SkySystem;
import org.openworld.engine.terrain.TerrainSystem;

/**
 * The water on real GL, over imported worlds built for the purpose: a flat sea bed 20 m under the water with a
 * 32 m square tower rising 80 m out of it, or the bed alone with a bank 2 m under the surface.
 */
@GlTest
class WaterRenderTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int W = 320;
    static final int H = 180;
    /** Samples per side of the imported maps, 2 m apart: a 512 m world. */
    static final int SAMPLES = 256;

    @TempDir
    static Path dir;
    static Path tower;
    static Path bank;

    /** Normalised heights: 0 the bed (−20 m with relief 100 and sea fraction 0.2), 1 the tower's top (+80 m). */
    @BeforeAll
    static void writeWorlds() throws IOException {
        tower = write("tower.raw", (x, z) -> x >= 120 && x < 136 && z >= 120 && z < 136 ? 1f : 0f);
        // the bank: 0.18 = 2 m under the water, 40 to 124 m south of the centre; and one sample at 1 (the south-east
        // corner, behind every camera here) so the range is 100 m
        bank = write("bank.raw", (x, z) -> x == SAMPLES - 1 && z == SAMPLES - 1 ? 1f
                : z >= 150 && z < 190 ? 0.18f : 0f);
    }

    static Path write(String name, ImportedWorld.Height height) throws IOException {
        return ImportedWorld.write(dir.resolve(name), SAMPLES, height);
    }

    static List<String> settings(Path world, String... more) {
        List<String> s = new ArrayList<>(List.of("terrain.import-file=" + world, "terrain.spacing=2",
                "terrain.relief=100", "terrain.sea-fraction=0.2", "clouds.cover=0", "water.reflection=FULL",
                "water.wind=0.5"));
        s.addAll(List.of(more));
        return s;
    }

    /** Looking north at the tower, 150 m away, from 10 m above the water: the waterline crosses the picture. */
    static final CameraPose AT_THE_TOWER = new CameraPose(0, 10, 150, 0, 0, 60);

    record Frame(Image picture, Image reflection) {
    }

    static Frame render(List<String> settings, CameraPose pose, Consumer<Engine> before) {
        WaterSystem water = new WaterSystem();
        try (Engine engine = GlTestSupport.engine(GL.context(), W, H, settings, new SkySystem(), new CullingSystem(),
                new TerrainSystem(), water)) {
            engine.world().resource(Camera.class).setPose(pose);
            before.accept(engine);
            engine.update();
            engine.render();
            Image picture = engine.readImage();
            Image reflection = water.reflectionTarget() == null ? null : water.reflectionTarget().read();
            return new Frame(picture, reflection);
        }
    }

    static Frame render(List<String> settings, CameraPose pose) {
        return render(settings, pose, engine -> { });
    }

    /** The picture row where a world point at this height appears on the tower's front face (pitch 0). */
    static double row(CameraPose pose, double height) {
        return rowOf(pose, new Vector4f(0, (float) height, 16, 1));
    }

    static double difference(Image a, int xa, int ya, Image b, int xb, int yb) {
        double d = 0;
        for (int c = 0; c < 3; c++) {
            d += Math.abs(a.channel(xa, ya, c) - b.channel(xb, yb, c));
        }
        return d / 3;
    }

    @Test
    void theTowerAppearsMirroredAboutTheWaterline() {
        Image picture = render(settings(tower, "water.method=STENCIL", "water.alpha=1"), AT_THE_TOWER).picture();
        int waterline = (int) Math.round(row(AT_THE_TOWER, 0));
        int column = W / 2;
        int beside = W / 2 + 60; // well clear of the tower's 32 m at 134 m (about 33 px either side of the centre)
        double mirrorError = 0;
        double towerAgainstSky = 0;
        int rows = 0;
        for (int k = 3; k <= 40; k++) {
            mirrorError += difference(picture, column, waterline - k, picture, column, waterline + k);
            towerAgainstSky += difference(picture, column, waterline + k, picture, beside, waterline + k);
            rows++;
        }
        // 12 levels (of 255, mean of R, G, B) for the mirror against > 40 for the sky beside it: the reflection matches
        // the tower three times better than anything else there; the water's own tint takes the rest
        assertTrue(mirrorError / rows < 12, "the tower's rows and their mirror rows differ by " + mirrorError / rows);
        assertTrue(towerAgainstSky / rows > 40, "the tower's reflection is not told from the sky's: "
                + towerAgainstSky / rows);
    }

    @Test
    void theFresnelWaterReflectsTheTowerToo() {
        Image picture = render(settings(tower), AT_THE_TOWER).picture();
        int waterline = (int) Math.round(row(AT_THE_TOWER, 0));
        double underTower = picture.meanLuma(W / 2 - 8, waterline + 4, W / 2 + 8, waterline + 30);
        double besideTower = picture.meanLuma(W / 2 + 60, waterline + 4, W / 2 + 76, waterline + 30);
        // 27 levels with the former hemisphere ambient, 19 since the shaded face gets the sky's and the ground's light
        assertTrue(besideTower - underTower > 15, "the dark tower should darken its reflection: under it "
                + underTower + ", beside it " + besideTower);
    }

    @Test
    void stencilAlphaZeroShowsTheGroundAndOneOnlyTheReflection() {
        Frame dry = render(settings(tower, "water.method=STENCIL"), AT_THE_TOWER,
                engine -> engine.setEnabled("water", false));
        Frame clear = render(settings(tower, "water.method=STENCIL", "water.alpha=0"), AT_THE_TOWER);
        Frame mirror = render(settings(tower, "water.method=STENCIL", "water.alpha=1"), AT_THE_TOWER);
        int waterline = (int) Math.round(row(AT_THE_TOWER, 0));
        int farFromTower = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                // one 8-bit level: blending with alpha 0 may round the last bit, no more
                assertTrue(difference(dry.picture(), x, y, clear.picture(), x, y) <= 1,
                        "alpha 0 changed (" + x + ", " + y + ")");
                if (y > waterline + 2 && Math.abs(x - W / 2) > 45) {
                    farFromTower++;
                    // two levels: the reflection texture sampled back through the blend, rounded twice
                    assertTrue(difference(mirror.picture(), x, y, mirror.reflection(), x, y) <= 2,
                            "alpha 1 is not the reflection at (" + x + ", " + y + ")");
                }
            }
        }
        assertTrue(farFromTower > W * H / 4);
        // and the water is not simply invisible: the mirror's picture differs from the dry one below the waterline
        // 10 levels of mean luma: plainly visible, far above the one-level rounding above
        assertTrue(Math.abs(mirror.picture().meanLuma(0, waterline + 3, W, H) - dry.picture().meanLuma(0,
                waterline + 3, W, H)) > 10);
    }

    /** Looking down at the water over the bank 2 m under it. */
    static final CameraPose OVER_THE_BANK = new CameraPose(0, 15, 200, 0, -12, 60);

    @Test
    void nothingUnderTheWaterLeaksIntoTheClippedReflection() {
        Frame withBank = render(settings(bank), OVER_THE_BANK);
        Frame withoutTerrain = render(settings(bank), OVER_THE_BANK, e -> e.setEnabled("terrain", false));
        assertEquals(0, maxDifference(withBank.reflection(), withoutTerrain.reflection()), 1,
                "the bed and the bank, both under the water, showed in the reflection");
        // the control: the paper's method does not clip, and there the bed shows
        Frame unclipped = render(settings(bank, "water.method=STENCIL"), OVER_THE_BANK);
        Frame unclippedEmpty = render(settings(bank, "water.method=STENCIL"), OVER_THE_BANK,
                e -> e.setEnabled("terrain", false));
        // the bed's ground against empty sky: dozens of levels; 30 is far above the clipped case's 1
        assertTrue(maxDifference(unclipped.reflection(), unclippedEmpty.reflection()) > 30);
    }

    @Test
    void bothMethodsGiveWaterThatIsNeitherBlackNorUniform() {
        for (String method : List.of("FRESNEL", "STENCIL")) {
            Image picture = render(settings(bank, "water.method=" + method, "water.wind=5"), OVER_THE_BANK).picture();
            double mean = picture.meanLuma(0, H / 2, W, H);
            double variance = 0;
            for (int y = H / 2; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    variance += Math.pow(picture.luma(x, y) - mean, 2);
                }
            }
            double deviation = Math.sqrt(variance / (W * H / 2.0));
            // 20 of 255: darker than any lit water or sky reflection, near black; a deviation under 3 levels is a flat
            // fill (the 8-bit step is 1)
            assertTrue(mean > 20, method + ": water too dark, mean luma " + mean);
            assertTrue(deviation > 3, method + ": water uniform, deviation " + deviation);
        }
    }

    /**
     * The ripples derive from the world seed: the same {@code engine.seed} draws the same water pixel for pixel,
     * another seed other ripples. Without the water the two seeds give the same picture (no terrain drawn, no
     * clouds), so the difference is the ripples'.
     */
    @Test
    void theRipplesFollowTheWorldSeed() {
        Consumer<Engine> noTerrain = e -> e.setEnabled("terrain", false);
        Consumer<Engine> noWater = e -> {
            e.setEnabled("terrain", false);
            e.setEnabled("water", false);
        };
        Image one = render(settings(bank, "water.wind=5", "engine.seed=1"), OVER_THE_BANK, noTerrain).picture();
        Image same = render(settings(bank, "water.wind=5", "engine.seed=1"), OVER_THE_BANK, noTerrain).picture();
        Image other = render(settings(bank, "water.wind=5", "engine.seed=2"), OVER_THE_BANK, noTerrain).picture();
        Image dryOne = render(settings(bank, "engine.seed=1"), OVER_THE_BANK, noWater).picture();
        Image dryOther = render(settings(bank, "engine.seed=2"), OVER_THE_BANK, noWater).picture();
        double sameSeed = 0;
        double otherSeed = 0;
        double dry = 0;
        int texels = W * (H / 2);
        for (int y = H / 2; y < H; y++) {
            for (int x = 0; x < W; x++) {
                sameSeed += difference(one, x, y, same, x, y) / texels;
                otherSeed += difference(one, x, y, other, x, y) / texels;
                dry += difference(dryOne, x, y, dryOther, x, y) / texels;
            }
        }
        assertEquals(0, sameSeed, "the same seed, the same water");
        assertEquals(0, dry, "without the water the seeds draw the same picture");
        // 1 level of mean difference: the same seed gives exactly 0, so any real change of ripples shows
        assertTrue(otherSeed > 1, "another seed, other ripples: mean difference " + otherSeed + " levels");
    }

    @Test
    void theShallowBankShowsThroughTheFresnelWater() {
        // looking steeply down through the water: over the bank (2 m deep) and over the bed (20 m deep)
        CameraPose overBank = new CameraPose(0, 15, 84, 0, -70, 60);
        CameraPose overBed = new CameraPose(0, 15, 220, 0, -70, 60);
        Image wetBank = render(settings(bank), overBank).picture();
        Image wetBed = render(settings(bank), overBed).picture();
        Image dryBank = render(settings(bank), overBank, e -> e.setEnabled("water", false)).picture();
        double seenBank = wetBank.meanLuma(W / 4, H / 4, 3 * W / 4, 3 * H / 4);
        double seenBed = wetBed.meanLuma(W / 4, H / 4, 3 * W / 4, 3 * H / 4);
        double dry = dryBank.meanLuma(W / 4, H / 4, 3 * W / 4, 3 * H / 4);
        // 10 and 5 levels of mean luma (of 255): chosen as plainly visible differences, not measured
        assertTrue(seenBank > seenBed + 10, "the bank " + seenBank + " should show brighter than the deep bed "
                + seenBed);
        assertTrue(dry - seenBank > 5, "the water should dim the bank a little: dry " + dry + ", wet " + seenBank);
        // the ground's texture shows through: the wet bank is far from uniform
        assertTrue(correlation(wetBank, dryBank) > 0.5, "the bank's pattern should show through the water");
    }

    /** Pearson correlation of two pictures' luma over their middle. */
    static double correlation(Image a, Image b) {
        double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
        int n = 0;
        for (int y = H / 4; y < 3 * H / 4; y++) {
            for (int x = W / 4; x < 3 * W / 4; x++) {
                double p = a.luma(x, y);
                double q = b.luma(x, y);
                sa += p;
                sb += q;
                saa += p * p;
                sbb += q * q;
                sab += p * q;
                n++;
            }
        }
        double cov = sab / n - sa / n * sb / n;
        return cov / Math.sqrt((saa / n - sa * sa / n / n) * (sbb / n - sb * sb / n / n));
    }

    @Test
    void underTheWaterThePictureIsTintedAndTheReflectionPassRests() {
        CameraPose diver = new CameraPose(0, -5, 250, 0, 40, 60);
        List<FrameRecord> records = new ArrayList<>();
        Image picture;
        try (Engine engine = GlTestSupport.engine(GL.context(), W, H, settings(bank), new SkySystem(),
                new CullingSystem(), new TerrainSystem(), new WaterSystem())) {
            engine.world().resource(Camera.class).setPose(diver);
            engine.update();
            engine.render();
            picture = engine.readImage();
            engine.world().resource(Camera.class).setPose(OVER_THE_BANK);
            engine.update();
            engine.render();
            engine.collectFrames(true, records::add);
        }
        double red = 0;
        double blue = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                red += picture.channel(x, y, 0);
                blue += picture.channel(x, y, 2);
            }
        }
        // the extinction set in WaterOpticsTest: red 0.35/m against blue 0.0145/m, so a few metres of water leave far
        // under 1/1.5 of the red; 15 levels of mean luma is "not black"
        assertTrue(blue > 1.5 * red, "under the water red is absorbed first: red " + red + ", blue " + blue);
        assertTrue(picture.meanLuma(0, 0, W, H) > 15, "not black");
        assertFalse(records.get(0).passGpuMs().containsKey("reflection.terrain"), records.get(0).passGpuMs().keySet()
                .toString());
        assertTrue(records.get(1).passGpuMs().containsKey("reflection.terrain"));
        assertTrue(records.get(1).passGpuMs().containsKey("reflection.sky"));
        assertEquals(0, GL.context().objects().live(), "live GL objects after close: " + GL.context().objects());
    }

    /**
     * The reflection pass draws only over the water's part of the screen: read back, its target (cleared to alpha 0,
     * covered with alpha 1 wherever the sky or the terrain draws) is empty above the horizon and full below it.
     */
    @Test
    void theReflectionPassTouchesNoPixelAboveTheHorizon() {
        // pitch 0: the horizon is the middle row; the water, and so the reflection it reads, fills the lower half
        Image reflection = render(settings(tower), AT_THE_TOWER).reflection();
        int horizon = reflection.height() / 2;
        int drawnAbove = 0;
        int emptyBelow = 0;
        for (int y = 0; y < reflection.height(); y++) {
            for (int x = 0; x < reflection.width(); x++) {
                boolean drawn = reflection.channel(x, y, 3) > 0;
                if (y < horizon - 1) {
                    drawnAbove += drawn ? 1 : 0;
                } else if (y > horizon + 1) {
                    emptyBelow += drawn ? 0 : 1;
                }
            }
        }
        assertEquals(0, drawnAbove, "reflection pixels drawn above the horizon, where no water is");
        assertEquals(0, emptyBelow, "reflection pixels left empty below the horizon, where the water is");
    }

    /**
     * The sea's horizon is as smooth along the picture as the cloudless sky it mirrors: looking level all round over
     * the open sea, no pixel of the sky's last row or the water's first rows stands more than 3 levels of luma off
     * the mean of its neighbours 3 pixels to either side. A horizon texel of the sky's panorama whose direction
     * rounded a hair below the horizon took the distant ground's light: a row of brighter dots a degree or so apart,
     * 7.6 levels on llvmpipe, in the sky's last row and, mirrored, in the water's first.
     */
    @Test
    void theSeaHorizonHasNoDots() {
        double worst = 0;
        String where = "";
        for (int yaw = 0; yaw < 360; yaw += 90) {
            // a 60° field is 91° wide at 16:9: four yaws see the whole horizon; the terrain off leaves open sea
            Image picture = render(settings(bank), new CameraPose(0, 50, 0, yaw, 0, 60),
                    e -> e.setEnabled("terrain", false)).picture();
            for (int y = H / 2 - 1; y <= H / 2 + 4; y++) {
                for (int x = 3; x < W - 3; x++) {
                    double bump = Math.abs(picture.luma(x, y) - (picture.luma(x - 3, y) + picture.luma(x + 3, y)) / 2);
                    if (bump > worst) {
                        worst = bump;
                        where = "yaw " + yaw + "°, (" + x + ", " + y + ")";
                    }
                }
            }
        }
        // 3 levels off the mean of its neighbours 3 px away: the horizon's real gradient gives 1–2, a dot dozens
        assertTrue(worst < 3, "a dot on the horizon: " + worst + " levels off its neighbours at " + where);
    }

    @Test
    void noReflectionPassWhenNoWaterIsOnScreen() {
        // 40 degrees up with a 60 degree field: the picture's lowest row looks 10 degrees above the horizon
        Frame frame = render(settings(tower), new CameraPose(0, 10, 150, 0, 40, 60));
        assertNull(frame.reflection(), "a reflection pass ran with no water in sight");
        // 20 of 255: a drawn sky is far brighter, an undrawn one is black
        assertTrue(frame.picture().meanLuma(0, 0, W, H) > 20, "the sky is drawn");
    }

    /** The picture row where the water surface at (0, z) appears. */
    static double rowOfZ(CameraPose pose, double z) {
        return rowOf(pose, new Vector4f(0, 0, (float) z, 1));
    }

    static double rowOf(CameraPose pose, Vector4f point) {
        Camera camera = new Camera();
        camera.setPose(pose);
        Vector4f clip = new Matrix4f(camera.view((float) W / H).viewProjection()).transform(point);
        return (1 - clip.y / clip.w) / 2 * H - 0.5;
    }

    static double maxDifference(Image a, Image b) {
        double max = 0;
        for (int y = 0; y < a.height(); y++) {
            for (int x = 0; x < a.width(); x++) {
                max = Math.max(max, difference(a, x, y, b, x, y));
            }
        }
        return max;
    }
}

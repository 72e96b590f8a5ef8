package org.openworld.engine.shadow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;
import org.joml.Vector3f;
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
import org.openworld.engine.environment.Sun;
import org.openworld.engine.gl.Image;
import org.openworld.engine.terrain.TerrainSystem;

/**
 * The terrain's levels of detail in the sun's pass, seen in the shadows they cast on rough generated mountains a
 * kilometre or more away: the shadowed fraction of the picture under the default screen-error rule stays near that of
 * a full-resolution reference (every patch at level 0, casters and receivers alike), at a high and at a low sun. The
 * paper's rule with its casters one level coarser than the ground that receives them ({@code lod.shadow-coarsening=1},
 * its default) is the counter-example: the coarse caster surface lies above the fine ground in every hollow, and the
 * hollows go dark in specks that no relief casts. Casters finer than the ground fail the other way: the ground goes
 * dark under every bump they keep and it lost.
 */
@GlTest
class CasterLevelsRenderTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int W = 480;
    static final int H = 270;
    /** Over the valley, looking north at the mountains beyond, as figure 9d does. */
    static final CameraPose POSE = new CameraPose(0, 400, 900, 0, 5, 60);
    static final List<String> WORLD = List.of("terrain.size=1024", "terrain.spacing=2");
    static final List<String> REFERENCE = List.of("lod.rule=PAPER", "lod.base-resolution=100000",
            "lod.shadow-coarsening=0");

    /** How far the shadowed fraction of the picture may stray from the full resolution's. */
    static final double TOLERANCE = 0.01;

    /** A sun in the south at this elevation, degrees. */
    static Sun southSun(double elevation) {
        double e = Math.toRadians(elevation);
        return new Sun(new Vector3f(0, (float) Math.sin(e), (float) Math.cos(e)), new Vector3f(1), new Vector3f(0.25f));
    }

    /**
     * The shadowed fraction of the picture under some level settings, for each sun elevation given: the fraction of
     * pixels drawn darker than 0.85 × the same picture without shadows. One world for all, maps redrawn every frame.
     */
    static double[] shadowed(List<String> lod, double... elevations) {
        return shadowed(WORLD, lod, ground -> POSE, elevations);
    }

    /** The same for a world and a pose placed over its ground. */
    static double[] shadowed(List<String> world, List<String> lod, Function<HeightField, CameraPose> pose,
                             double... elevations) {
        List<String> settings = new ArrayList<>(world);
        settings.addAll(lod);
        settings.add("shadow.refresh=ALWAYS");
        double[] fractions = new double[elevations.length];
        try (Engine engine = GlTestSupport.engine(GL.context(), W, H, settings, new CullingSystem(),
                new TerrainSystem(), new ShadowSystem())) {
            engine.world().resource(Camera.class).setPose(pose.apply(engine.world().resource(HeightField.class)));
            for (int i = 0; i < elevations.length; i++) {
                engine.world().setResource(southSun(elevations[i]));
                Image lit = frame(engine, false);
                Image image = frame(engine, true);
                int dark = 0;
                for (int y = 0; y < H; y++) {
                    for (int x = 0; x < W; x++) {
                        dark += image.luma(x, y) < 0.85 * lit.luma(x, y) ? 1 : 0;
                    }
                }
                fractions[i] = (double) dark / (W * H);
            }
        }
        return fractions;
    }

    private static Image frame(Engine engine, boolean shadows) {
        engine.setEnabled("shadow", shadows);
        engine.update();
        engine.render();
        return engine.readImage();
    }

    /**
     * Measured (480 × 270): at 54° the full resolution shadows 0.06 % of the picture, the screen-error rule 0.21 %,
     * the paper's coarse casters 2.4 %; at 10° the full resolution 7.8 %, the screen-error rule 6.9 %. Casters cut by
     * a cascade's texels alone, finer than the viewer's ground, shadowed 12.7 % at 54°: the ground under every bump
     * they keep and it lost.
     */
    @Test
    void theDefaultRuleShadowsTheMountainsAsTheFullResolutionDoes() {
        double[] elevations = {54, 10};
        double[] reference = shadowed(REFERENCE, elevations);
        double[] screenError = shadowed(List.of(), elevations);
        double[] coarseCasters = shadowed(List.of("lod.rule=PAPER", "lod.shadow-coarsening=1"), elevations[0]);
        for (int i = 0; i < elevations.length; i++) {
            String series = "sun " + elevations[i] + "°: full resolution " + reference[i] + ", screen error "
                    + screenError[i];
            System.out.println("caster levels, " + series);
            // 0.02 % of the picture: about 26 pixels of 480 × 270, a shadow that is there at all
            assertTrue(reference[i] > 0.0002, "the mountains cast shadows at all: " + series);
            assertEquals(reference[i], screenError[i], TOLERANCE, "shadowed fraction of the picture, " + series);
        }
        // the counter-example, which the tolerance tells apart
        assertTrue(coarseCasters[0] > reference[0] + 2 * TOLERANCE, "the paper rule's casters, a level coarser "
                + "than the ground: " + coarseCasters[0] + " of the picture shadowed, full resolution " + reference[0]);
    }

    /**
     * The unbounded world's relief casts its shadows too, through the same caster cut (its streamed heights, its
     * uniform per-level errors): 300 m over the ground at the start of {@code crossing.path}, looking east and down
     * at the hills, a 10° sun in the south shadows far more of the picture than a 54° one, whose shadows are short.
     * Measured (480 × 270): 54°: 0.4 %, 10°: 17.0 %.
     */
    @Test
    void theUnboundedWorldsReliefCastsShadows() {
        double[] fractions = shadowed(List.of("terrain.world=unbounded"), List.of(),
                ground -> new CameraPose(-9000, ground.heightAt(-9000, 0) + 300, 0, 90, -10, 60), 54, 10);
        String series = "unbounded world: sun 54° " + fractions[0] + ", 10° " + fractions[1];
        System.out.println("caster levels, " + series);
        // measured 17.0 % and 0.4 % (above): 5 % and a 3-point gap hold the long low-sun shadows with a wide margin
        assertTrue(fractions[1] > 0.05 && fractions[1] > fractions[0] + 0.03, series);
    }
}

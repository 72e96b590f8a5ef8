package org.openworld.engine.elevation;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
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
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.gl.Image;
import org.openworld.engine.sky.SkySystem;
import org.openworld.engine.terrain.TerrainSystem;
import org.openworld.engine.water.WaterSystem;

/**
 * The shipped real place on real GL, at true scale: water raised to a level in metres between a valley's height and a
 * ridge's, both read from the file, covers the valley and leaves the ridge. With the heights normalised instead
 * ({@code terrain.import-scale=false}) the same level misses: the valley lies elsewhere in height.
 */
@GlTest
class RealPlaceRenderTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final Path DEM = Path.of("../assets/elevation/jacksboro-fault.tif");
    static final int SIDE = 48;
    /** The eye above the point it looks straight down on, metres: far enough that 48 px span about 350 m. */
    static final double ABOVE = 300;

    @Test
    void waterAtALevelInMetresCoversTheValleyAndLeavesTheRidge() {
        ElevationGrid grid = ElevationImport.grid(DEM, ElevationImportTest.settings());
        int[] low = extreme(grid, false);
        int[] high = extreme(grid, true);
        double lowHeight = grid.at(low[0], low[1]);
        double highHeight = grid.at(high[0], high[1]);
        double level = (lowHeight + highHeight) / 2;

        double valleyChange = change(grid, low, level);
        double ridgeChange = change(grid, high, level);
        // water (dark blue, mirroring the sky) against grass or rock: tens of levels; the ridge's pixels are the same
        // frames but for the water plane hidden under it, so only the sky's reflection in nothing: no change
        assertTrue(valleyChange > 20, "the valley at " + lowHeight + " m should be under water at " + level
                + " m: its centre changed by " + valleyChange);
        assertTrue(ridgeChange < 2, "the ridge at " + highHeight + " m should stay dry at " + level
                + " m: its centre changed by " + ridgeChange);
    }

    /** Mean change of the picture's centre (the point looked down on) when the water rises from 0 to the level. */
    private static double change(ElevationGrid grid, int[] at, double level) {
        double x = at[0] * grid.spacingX() - grid.extentX() / 2;
        double z = at[1] * grid.spacingZ() - grid.extentZ() / 2;
        CameraPose pose = new CameraPose(x, grid.at(at[0], at[1]) + ABOVE, z, 0, -89, 60);
        Image dry = render(pose, "water.level=0");
        Image wet = render(pose, "water.level=" + level);
        int c = SIDE / 2;
        double d = 0;
        for (int k = 0; k < 3; k++) {
            for (int y = c - 2; y <= c + 2; y++) {
                for (int xx = c - 2; xx <= c + 2; xx++) {
                    d += Math.abs(dry.channel(xx, y, k) - wet.channel(xx, y, k));
                }
            }
        }
        return d / 75;
    }

    private static Image render(CameraPose pose, String water) {
        List<String> settings = new ArrayList<>(List.of("terrain.import-file=" + DEM, "terrain.import-detail=false",
                "clouds.cover=0", water));
        try (Engine engine = GlTestSupport.engine(GL.context(), SIDE, SIDE, settings, new SkySystem(),
                new CullingSystem(), new TerrainSystem(), new WaterSystem())) {
            engine.world().resource(Camera.class).setPose(pose);
            engine.update();
            engine.render();
            return engine.readImage();
        }
    }

    /** The lowest or highest sample of the model's central half, where its surroundings are the model too. */
    private static int[] extreme(ElevationGrid g, boolean highest) {
        int[] best = null;
        for (int z = g.height() / 4; z < 3 * g.height() / 4; z++) {
            for (int x = g.width() / 4; x < 3 * g.width() / 4; x++) {
                if (best == null || (highest ? g.at(x, z) > g.at(best[0], best[1])
                        : g.at(x, z) < g.at(best[0], best[1]))) {
                    best = new int[] {x, z};
                }
            }
        }
        return best;
    }
}

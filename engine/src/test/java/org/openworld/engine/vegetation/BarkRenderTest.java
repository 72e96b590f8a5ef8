package org.openworld.engine.vegetation;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.gl.Image;

/**
 * The synthesised bark on real GL: a trunk seen from 2.5 m wears the texture's plates and furrows up its length, not
 * one flat colour. On {@link TreeRenderTest}'s shore world and context, without shadows (whose edges would also
 * vary a trunk's shade) and in a still air.
 */
@GlTest
class BarkRenderTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    @TempDir
    static Path dir;

    /** Metres from the trunk's axis to the eye, and the eye's height over the foot. */
    static final double NEAR = 2.5;
    static final double EYE = 1.0;

    @Test
    void aNearTrunkWearsTheBarksPlatesUpItsLength() throws IOException {
        TreeRenderTest.shore = TreeRenderTest.writeShore(dir);
        VegetationSystem trees = new VegetationSystem();
        try (Engine engine = TreeRenderTest.engine(GL.context(), trees,
                new CameraPose(-60, 12, 0, 270, 0, 60), List.of())) {
            engine.world().setResource(TreeRenderTest.EAST_SUN);
            TreeRenderTest.frame(engine, "vegetation", true);
            float[] trunk = loneTrunk(trees);
            assertNotNull(trunk, "no tree with 5 m clear east of it");
            // east of the trunk, looking west at its sunlit side
            engine.world().resource(Camera.class).setPose(new CameraPose(trunk[0] + NEAR, trunk[1] + EYE, trunk[2],
                    270, 0, 60));
            engine.update();
            trees.settle(engine.world());
            engine.render();
            Image image = engine.readImage();
            // the trunk's middle column, from 0.4 m to 2 m up (the bare stem under either kind's crown)
            int[] low = TreeRenderTest.pixel(engine, trunk[0], trunk[1] + 0.4, trunk[2]);
            int[] high = TreeRenderTest.pixel(engine, trunk[0], trunk[1] + 2.0, trunk[2]);
            assertNotNull(low, "the trunk's foot is out of the picture");
            assertNotNull(high, "the trunk's top is out of the picture");
            int rows = 0;
            int steps = 0;
            for (int y = high[1]; y < low[1]; y++) {
                rows++;
                steps += Math.abs(image.luma(low[0], y + 1) - image.luma(low[0], y)) >= 2 ? 1 : 0;
            }
            // An untextured stem is shaded alike all the way up (its normal does not change along it, the air between
            // is 2 m): its 8-bit luma moves by under a level from row to row, so a step of 2 levels comes only where
            // a crown's edge crosses it (4 rows of 100 here with flat bark). The bark's plates, 6 to 30 cm tall, a
            // few pixels to a few tens here (1.4 cm a pixel), darken by up to 45 % into their furrows: expect a step
            // of 2 levels or more at every tenth row at least (37 with the bark).
            assertTrue(rows >= 60, "rows over the trunk: " + rows);
            assertTrue(steps >= 0.1 * rows, "luma steps of 2 levels or more up the trunk: " + steps + " of " + rows);
        }
    }

    /** The foot of the conifer or broadleaf tree with no other plant's foot within 5 m east of it, or null. */
    static float[] loneTrunk(VegetationSystem trees) {
        float[] placed = trees.placed();
        for (int i = 0; i < placed.length; i += TreePlacement.FLOATS) {
            if (TreePlacementTest.kindOf(trees.layout(), i / TreePlacement.FLOATS) == TreeKind.BUSH
                    || placed[i] > -20) {
                continue;
            }
            boolean clear = true;
            for (int j = 0; j < placed.length && clear; j += TreePlacement.FLOATS) {
                double east = placed[j] - placed[i];
                clear = j == i || !(east > -1 && east < 5 && Math.abs(placed[j + 2] - placed[i + 2]) < 3);
            }
            if (clear) {
                return new float[] {placed[i], placed[i + 1], placed[i + 2]};
            }
        }
        return null;
    }
}

package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL11C.GL_FLOAT;
import static org.lwjgl.opengl.GL11C.GL_RGBA;
import static org.lwjgl.opengl.GL11C.glBindTexture;
import static org.lwjgl.opengl.GL11C.glGetTexImage;
import static org.lwjgl.opengl.GL12C.GL_TEXTURE_3D;

import java.nio.file.Path;
import java.util.Arrays;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.openworld.engine.camera.CameraDirection;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.environment.SkyMaps;
import org.openworld.engine.gl.Image;
import org.openworld.engine.gl.Texture3D;
import org.openworld.engine.terrain.heights.TerrainSettings;
import picocli.CommandLine;

/**
 * The camera's pose reaches every system of the frame it is shown in, whatever command asked for it: a shot is the
 * picture the same pose gives after any number of frames, and the sky's tables of a shot are made for the shot's own
 * altitude.
 */
@Tag("gl")
class CameraDirectorTest {

    /**
     * A small world that does not move: no clouds (they drift and evolve), no water (its ripples move), no plants
     * (their crowns and the grass sway in the wind), no temporal anti-aliasing (it jitters every frame and blends it with the last,
     * so frames at one pose differ by design).
     */
    private static final String[] STILL = {"--size", "160x90", "--time", "16:00", "--set", "terrain.size=256",
            "--set", "clouds.cover=0", "--set", "system.water=off", "--set", "system.vegetation=off", "--set", "system.grass=off", "--set",
            "antialias.method=off"};

    @TempDir
    Path dir;

    /**
     * On both worlds: the unbounded one streams its levels around the camera, and a shot waits for them, so it shows
     * what later frames at its pose show. The pose lies over the ground of either world (210 m over the unbounded
     * one's).
     */
    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    void aShotIsTheFrameAfterManyFramesAtItsPose(TerrainSettings.World world) throws Exception {
        String pose = "-300,600,700,20,-12";
        String[] still = concat(STILL, "--set", "terrain.world=" + world);
        Path shot = dir.resolve("shot.png");
        assertEquals(0, Main.execute(concat(still, "shot", "--out", shot.toString(), "--camera", pose)));

        Image settled;
        try (Launch launch = Launch.start(options(still), false, "test")) {
            Poses.direct(launch.engine.world(), CameraDirection.fixed(camera(pose)));
            for (int frame = 0; frame < 6; frame++) {
                launch.engine.update();
                launch.engine.render();
            }
            settled = ShotCommand.opaque(launch.engine.readImage());
        }
        Image first = Image.read(shot);
        int differing = 0;
        int largest = 0;
        String where = "";
        for (int y = 0; y < first.height(); y++) {
            for (int x = 0; x < first.width(); x++) {
                for (int c = 0; c < 3; c++) {
                    int d = Math.abs(first.channel(x, y, c) - settled.channel(x, y, c));
                    differing += d != 0 ? 1 : 0;
                    if (d > largest) {
                        largest = d;
                        where = " at (" + x + ", " + y + ")";
                    }
                }
            }
        }
        assertEquals(0, differing, "channels that differ between the shot and the sixth frame at its pose; the largest "
                + "by " + largest + where);
    }

    @Test
    void aShotsSkyTablesAreMadeForItsAltitude() {
        float[] high = aerialPerspectiveOfAShotAt(2500);
        float[] low = aerialPerspectiveOfAShotAt(100);
        assertEquals(high.length, low.length);
        assertTrue(!Arrays.equals(high, low), "the air between the eye and the ground differs between 2500 m and 100 m");
        float[] again = aerialPerspectiveOfAShotAt(2500);
        assertArrayEquals(high, again, "and the same altitude gives the same tables");
    }

    /** The aerial-perspective volume after a shot's update at this altitude (the shot's own sequence of calls). */
    private static float[] aerialPerspectiveOfAShotAt(double altitude) {
        try (Launch launch = Launch.start(options(STILL), false, "test")) {
            ShotCommand.prepare(launch, CameraDirection.fixed(new CameraPose(0, altitude, 0, 0, -5, 60)));
            launch.engine.render();   // the tables go up to the GPU where they are drawn with
            Texture3D air = launch.engine.world().resource(SkyMaps.class).aerialPerspective();
            float[] texels = new float[air.width() * air.height() * air.depth() * 4];
            glBindTexture(GL_TEXTURE_3D, air.id());
            glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_FLOAT, texels);
            glBindTexture(GL_TEXTURE_3D, 0);
            return texels;
        }
    }

    private static RenderOptions options(String... args) {
        ShotCommand shot = new ShotCommand();
        new CommandLine(shot).parseArgs(concat(args, "--out", "unused.png"));
        return shot.render;
    }

    private static CameraPose camera(String text) {
        return new PoseOptions.PoseConverter().convert(text);
    }

    private static String[] concat(String[] options, String... more) {
        String[] all = Arrays.copyOf(more, more.length + options.length);
        System.arraycopy(options, 0, all, more.length, options.length);
        return all;
    }
}

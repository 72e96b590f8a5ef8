package org.openworld.engine.shadow;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.joml.Vector3f;
import org.openworld.engine.ImportedWorld;
import org.openworld.engine.environment.Sun;

/**
 * A world built for shadow tests: flat ground at −20 m and a wall 100 m high and 16 m thick running north–south just
 * west of the centre (x from −16 to 0 m), lit by a sun in the east 35° up, so the wall's shadow lies on the ground
 * west of it, 100 / tan 35° = 143 m long (x from −159 to −16 m).
 */
public final class WallWorld {

    /** Samples per side of the imported map, 2 m apart: a 512 m world from −256 to 256 m. */
    static final int SAMPLES = 256;
    /** Height of the flat ground, metres. */
    public static final double GROUND = -20;
    static final double ELEVATION = Math.toRadians(35);
    public static final Sun EAST_SUN = new Sun(new Vector3f((float) Math.cos(ELEVATION),
            (float) Math.sin(ELEVATION), 0), new Vector3f(1), new Vector3f(0.25f));

    private WallWorld() {
    }

    /** Writes the world as a raw float32 height map into {@code dir}. */
    public static Path write(Path dir) throws IOException {
        return ImportedWorld.write(dir.resolve("wall.raw"), SAMPLES, (x, z) -> x >= 120 && x < 128 ? 1f : 0f);
    }

    /**
     * The same wall on ground that rises westwards at {@code slopeDeg} (facing east, towards a morning sun): the
     * ground at {@link #slopedGround}, the wall 100 m above it. Import with {@link #slopedTerrain}.
     */
    public static Path writeSloped(Path dir, double slopeDeg) throws IOException {
        return ImportedWorld.write(dir.resolve("sloped-wall.raw"), SAMPLES,
                (x, z) -> (float) (slopedGround(slopeDeg, 2.0 * (x - SAMPLES / 2)) + (x >= 120 && x < 128 ? 100 : 0)));
    }

    /** Height of the sloped ground at x (metres east of the centre): {@link #GROUND} at x = 0. */
    public static double slopedGround(double slopeDeg, double x) {
        return GROUND - Math.tan(Math.toRadians(slopeDeg)) * x;
    }

    /**
     * The terrain settings that import {@link #writeSloped}'s map at its heights: the import normalises the samples
     * to 0..1, so the relief is the ground's rise from the east edge (x = 254 m) to the west (x = −256 m), the
     * wall's top being lower, and the sea fraction puts 0 m where it was.
     */
    public static List<String> slopedTerrain(Path wall, double slopeDeg) {
        double low = slopedGround(slopeDeg, 2.0 * (SAMPLES - 1 - SAMPLES / 2));
        double relief = slopedGround(slopeDeg, -2.0 * (SAMPLES / 2)) - low;
        return List.of("terrain.import-file=" + wall, "terrain.spacing=2", "terrain.relief=" + relief,
                "terrain.sea-fraction=" + (-low / relief));
    }

    /** The terrain settings that import it: 2 m apart, 0 → −20 m and 1 → 80 m. */
    public static List<String> terrain(Path wall) {
        return List.of("terrain.import-file=" + wall, "terrain.spacing=2", "terrain.relief=100",
                "terrain.sea-fraction=0.2");
    }
}

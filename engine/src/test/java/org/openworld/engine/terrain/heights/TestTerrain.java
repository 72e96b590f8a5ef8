package org.openworld.engine.terrain.heights;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.List;
import org.openworld.engine.settings.Settings;

/** Helpers shared by the terrain tests. */
public final class TestTerrain {

    private TestTerrain() {
    }

    /** Terrain settings from the defaults with {@code key=value} assignments applied, as {@code --set} does. */
    public static TerrainSettings settings(String... assignments) {
        Settings settings = new Settings(List.of(TerrainSettings.SETTINGS));
        for (String a : assignments) {
            settings.apply(a);
        }
        return settings.get(TerrainSettings.class);
    }

    /** A hash of the exact bits of every sample: equal only for bit-identical maps. */
    public static long bitsHash(float[] values) {
        ByteBuffer bytes = ByteBuffer.allocate(values.length * Float.BYTES).order(ByteOrder.LITTLE_ENDIAN);
        bytes.asFloatBuffer().put(values);
        long h = 1125899906842597L;
        for (byte b : bytes.array()) {
            h = 31 * h + b;
        }
        return h;
    }
}

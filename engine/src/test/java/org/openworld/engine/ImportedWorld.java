package org.openworld.engine;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Writes a height map for {@code terrain.import-file}: raw little-endian float32 samples, row by row from the north,
 * as the terrain imports them. Tests build worlds for their purpose with it (a shore, a wall, a tower).
 */
public final class ImportedWorld {

    /** A sample's normalised height, 0 the lowest and 1 the highest. */
    public interface Height {
        float at(int x, int z);
    }

    private ImportedWorld() {
    }

    /** Writes {@code samples}² samples to {@code file} and returns it. */
    public static Path write(Path file, int samples, Height height) throws IOException {
        ByteBuffer bytes = ByteBuffer.allocate(4 * samples * samples).order(ByteOrder.LITTLE_ENDIAN);
        for (int z = 0; z < samples; z++) {
            for (int x = 0; x < samples; x++) {
                bytes.putFloat(height.at(x, z));
            }
        }
        return Files.write(file, bytes.array());
    }
}

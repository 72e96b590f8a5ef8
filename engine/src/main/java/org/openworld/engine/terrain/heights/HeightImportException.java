package org.openworld.engine.terrain.heights;

import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.failure.UserFacing;

/**
 * A height map file cannot be imported: the message names the file and what is wrong with it (missing, 8-bit, not
 * square, a size that is not 2^n or 2^n + 1, an unknown extension), so it can be shown to the user as it is.
 */
public final class HeightImportException extends RuntimeException implements UserFacing {
    public HeightImportException(String message) {
        super(message);
    }

    @Override
    public ExitCode exitCode() {
        return ExitCode.USER_MISTAKE;
    }
}

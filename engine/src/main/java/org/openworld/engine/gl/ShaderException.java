package org.openworld.engine.gl;

import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.failure.UserFacing;

/**
 * A shader could not be read, included, compiled or linked, or a uniform it should have is missing. The message
 * names the file and line in {@code shaders/}, never the line of the expanded source the driver saw.
 */
public final class ShaderException extends RuntimeException implements UserFacing {
    public ShaderException(String message) {
        super(message);
    }

    @Override
    public ExitCode exitCode() {
        return ExitCode.INTERNAL_FAILURE;
    }
}

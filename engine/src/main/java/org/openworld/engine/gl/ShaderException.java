package org.openworld.engine.gl;

import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.failure.UserFacing;

/**
 * A shader could not be read, included, compiled or linked, or a uniform it should have is missing. The message
 * names the file and line in {@code shaders/}, never the line of the expanded source the driver saw. A compile or
 * link failure is one paragraph: a heading naming the program and its files, then every line of the driver's log,
 * each put at its file and line ({@link ShaderLog}), e.g.
 * <pre>
 * program terrain/terrain.vert+terrain/terrain.frag: shaders/terrain/terrain.frag (with ...) did not compile:
 * shaders/common/fog.glsl:15:26: error: `toPointt' undeclared</pre>
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

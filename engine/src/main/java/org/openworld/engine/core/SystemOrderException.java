package org.openworld.engine.core;

import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.failure.UserFacing;

/** The systems' declarations admit no frame order: a cycle, two unordered writers, or an unknown name. */
public final class SystemOrderException extends RuntimeException implements UserFacing {
    public SystemOrderException(String message) {
        super(message);
    }

    @Override
    public ExitCode exitCode() {
        return ExitCode.INTERNAL_FAILURE;
    }
}

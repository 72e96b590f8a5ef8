package org.openworld.demo;

import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.failure.UserFacing;

/** A mistake in what the user asked for: printed as one message, exit code 2, no stack trace. */
final class UserError extends RuntimeException implements UserFacing {
    UserError(String message) {
        super(message);
    }

    @Override
    public ExitCode exitCode() {
        return ExitCode.USER_MISTAKE;
    }
}

package org.openworld.engine.settings;

import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.failure.UserFacing;

/** A setting key or value is invalid; the message names the key and what is valid. */
public final class SettingsException extends RuntimeException implements UserFacing {
    public SettingsException(String message) {
        super(message);
    }

    @Override
    public ExitCode exitCode() {
        return ExitCode.USER_MISTAKE;
    }
}

package org.openworld.engine.settings;

/** A setting key or value is invalid; the message names the key and what is valid. */
public final class SettingsException extends RuntimeException {
    public SettingsException(String message) {
        super(message);
    }
}

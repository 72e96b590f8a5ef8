package org.openworld.engine.core;

/** The systems' declarations admit no frame order: a cycle, two unordered writers, or an unknown name. */
public final class SystemOrderException extends RuntimeException {
    public SystemOrderException(String message) {
        super(message);
    }
}

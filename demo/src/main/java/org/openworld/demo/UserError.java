package org.openworld.demo;

/** A mistake in what the user asked for: printed as one message, exit code 2, no stack trace. */
final class UserError extends RuntimeException {
    UserError(String message) {
        super(message);
    }
}

package org.openworld.engine.gl;

/**
 * A shader could not be read, included, compiled or linked, or a uniform it should have is missing. The message
 * names the file and line in {@code shaders/}, never the line of the expanded source the driver saw.
 */
public final class ShaderException extends RuntimeException {
    public ShaderException(String message) {
        super(message);
    }
}

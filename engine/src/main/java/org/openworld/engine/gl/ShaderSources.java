package org.openworld.engine.gl;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;

/**
 * Where GLSL files come from: the classpath (the packaged {@code shaders/} folder) or, in dev mode, the
 * {@code shaders/} folder on disk so an edited file is picked up by a reload (F5). Paths are relative to that folder
 * and use '/', e.g. {@code common/frame.glsl}.
 */
public interface ShaderSources {

    /** The text of one file, or empty when there is none. */
    Optional<String> read(String path);

    /** How to name a file in messages, e.g. {@code shaders/sky/sky.frag}. */
    default String displayName(String path) {
        return "shaders/" + path;
    }

    /** The files packaged with the engine. */
    static ShaderSources classpath() {
        return path -> {
            try (InputStream in = ShaderSources.class.getResourceAsStream("/shaders/" + path)) {
                return in == null ? Optional.empty() : Optional.of(new String(in.readAllBytes(), StandardCharsets.UTF_8));
            } catch (IOException e) {
                throw new ShaderException("shaders/" + path + ": cannot read: " + e.getMessage());
            }
        };
    }

    /** Files under a folder on disk, read afresh on every call (dev mode). */
    static ShaderSources directory(Path root) {
        return new ShaderSources() {
            @Override
            public Optional<String> read(String path) {
                Path file = root.resolve(path);
                try {
                    return Files.isRegularFile(file) ? Optional.of(Files.readString(file)) : Optional.empty();
                } catch (IOException e) {
                    throw new ShaderException(file + ": cannot read: " + e.getMessage());
                }
            }

            @Override
            public String displayName(String path) {
                return root.resolve(path).toString();
            }
        };
    }
}

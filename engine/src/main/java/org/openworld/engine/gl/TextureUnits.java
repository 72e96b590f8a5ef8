package org.openworld.engine.gl;

import java.util.ArrayList;
import java.util.List;

/**
 * Hands out a system's texture units: each sampler it adds gets the next free unit from 0, below the units of the
 * {@link SharedTexture}s, so no unit is numbered by hand and two samplers of one system never share one. Each system
 * keeps its own (the units are bound again before each draw), usually as static constants:
 * <pre>{@code
 * private static final TextureUnits UNITS = new TextureUnits();
 * private static final TextureUnits.Sampler SCENE = UNITS.add("scene");
 * ...
 * program.sampler(SCENE);            // at link time
 * scene.color().bind(SCENE.unit());  // before the draw
 * }</pre>
 */
public final class TextureUnits {

    private final List<String> samplers = new ArrayList<>();

    /**
     * A sampler of the shaders and the unit its texture is bound to.
     *
     * @param name the sampler's name in GLSL
     * @param unit the texture unit
     */
    public record Sampler(String name, int unit) {
    }

    /** The sampler {@code name} on the next free unit. */
    public Sampler add(String name) {
        if (samplers.contains(name)) {
            throw new IllegalArgumentException("sampler '" + name + "' already has unit " + samplers.indexOf(name));
        }
        if (samplers.size() == SharedTexture.lowestUnit()) {
            throw new IllegalStateException("sampler '" + name + "': units 0-" + (samplers.size() - 1) + " are taken ("
                    + String.join(", ", samplers) + ") and the shared textures hold the rest");
        }
        samplers.add(name);
        return new Sampler(name, samplers.size() - 1);
    }
}

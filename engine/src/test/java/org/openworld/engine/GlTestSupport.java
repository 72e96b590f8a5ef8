package org.openworld.engine;

import java.util.List;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.ShaderSources;
import org.openworld.engine.settings.Settings;

/**
 * Builds engines for headless GL tests: small images, classpath shaders, default settings but for the world, which is
 * the tile ({@code terrain.world=tile}) unless a test names one: most tests draw a small {@code terrain.size} map and
 * look at what one seed makes there, which the unbounded world (the default) does not hold.
 */
public final class GlTestSupport {

    private static final String WORLD = "terrain.world";
    private static final String ANTIALIAS = "antialias.method";

    private GlTestSupport() {
    }

    public static Engine engine(GlContext gl, int width, int height, EngineSystem... systems) {
        return engine(gl, width, height, List.of(), systems);
    }

    /**
     * An engine whose settings have these {@code key=value} assignments applied before the systems start, on the
     * tile unless they name {@code terrain.world}, and without anti-aliasing unless they name
     * {@code antialias.method}: a system's test reads back what the system drew, not its edges blended by FXAA.
     */
    public static Engine engine(GlContext gl, int width, int height, List<String> settings, EngineSystem... systems) {
        List<EngineSystem> list = List.of(systems);
        Settings all = Engine.settingsFor(list);
        if (all.keys().contains(WORLD)) {
            all.set(WORLD, "tile"); // before the test's own, so a test that names the world gets it
        }
        all.set(ANTIALIAS, "off");
        settings.forEach(all::apply);
        return new Engine(gl, ShaderSources.classpath(), all, list, width, height);
    }

    /** One triangle that covers the whole viewport, corners in clip space at attribute 0 (vec2). */
    public static Mesh fullScreenTriangle(GlContext gl) {
        return Mesh.fullScreenTriangle(gl);
    }

    /** A quad of two triangles over the lower-left quarter of the viewport, attribute 0 (vec2). */
    public static Mesh quarterQuad(GlContext gl) {
        return new Mesh(gl, new float[] {-1, -1, 0, -1, 0, 0, -1, 0}, new int[] {0, 1, 2, 0, 2, 3},
                new Mesh.Attribute(0, 2));
    }
}

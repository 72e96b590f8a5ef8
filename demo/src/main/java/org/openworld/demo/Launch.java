package org.openworld.demo;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.openworld.engine.camera.CameraDirection;
import org.openworld.engine.Engine;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.ShaderSources;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsException;
import org.openworld.engine.settings.SettingsFile;
import org.openworld.engine.terrain.heights.TerrainSettings;

/**
 * One place that turns the common options into a running engine: settings with the user's {@code --set} values,
 * the GL context (window or headless), the shader sources (packaged, or {@code ./shaders} in dev mode), the engine
 * with the demo's systems, and the time of day. Each command then sets the camera's pose.
 */
final class Launch implements AutoCloseable {

    private static final String WORLD_KEY = "terrain.world";

    final GlContext gl;
    /** The running engine; the window's "Rebuild world" replaces it. */
    Engine engine;
    /** Whether shaders come from ./shaders on disk (--dev), so a reload picks up edits. */
    final boolean devShaders;
    private final ShaderSources shaders;

    private Launch(GlContext gl, Engine engine, boolean devShaders, ShaderSources shaders) {
        this.gl = gl;
        this.engine = engine;
        this.devShaders = devShaders;
        this.shaders = shaders;
    }

    /**
     * Settings of the demo's systems: the defaults, then the {@code --preset}, then the {@code --config} file, then
     * {@code --seed}, then every {@code --set} (all checked before any window opens). An imported map is always the
     * tile ({@link TerrainSettings}); a {@code --set terrain.world=unbounded} beside one is refused, since only a
     * {@code --set} is surely the user's word (a settings file holds every key, the default world too).
     */
    static Settings settings(RenderOptions options) {
        Settings settings = Engine.settingsFor(DemoScene.systems());
        if (options.preset != null) {
            Presets.apply(options.preset, settings);
        }
        if (options.config != null) {
            SettingsFile.read(options.config, settings);
        }
        if (options.seed != null) {
            settings.set("engine.seed", Integer.toString(options.seed));
        }
        String namedWorld = null;
        for (String assignment : options.set) {
            settings.apply(assignment); // checks key=value, so the split below is safe
            int eq = assignment.indexOf('=');
            if (assignment.substring(0, eq).trim().equals(WORLD_KEY)) {
                namedWorld = assignment.substring(eq + 1).trim();
            }
        }
        TerrainSettings terrain = settings.get(TerrainSettings.class);
        if (terrain.imports() && "unbounded".equalsIgnoreCase(namedWorld)) {
            throw new SettingsException(WORLD_KEY + "=unbounded cannot go with terrain.import-file="
                    + terrain.importFile() + ": an imported map is one tile; leave out " + WORLD_KEY
                    + " (an import always draws the tile)");
        }
        return settings;
    }

    /**
     * Headless, or a window without vsync: the commands that render a fixed number of frames. A {@code --size} too
     * large for memory is refused before the context is made, one too large for this OpenGL before the world is
     * built ({@link Size}).
     */
    static Launch start(RenderOptions options, boolean window, String title) {
        return start(options, window, false, title);
    }

    static Launch start(RenderOptions options, boolean window, boolean vsync, String title) {
        return start(options, window, vsync, false, title);
    }

    /** As {@link #start(RenderOptions, boolean, String)}, on a context with a GLFW window for Dear ImGui. */
    static Launch startWithGui(RenderOptions options, boolean window, String title) {
        return start(options, window, false, true, title);
    }

    private static Launch start(RenderOptions options, boolean window, boolean vsync, boolean gui, String title) {
        Settings settings = settings(options);
        double daySpeed = options.daySpeed(0);
        ShaderSources shaders = options.dev ? devShaders() : ShaderSources.classpath();
        List<EngineSystem> systems = DemoScene.systems();
        options.size.checkMemory();
        GlContext gl = window
                ? GlContext.window(title, options.size.width(), options.size.height(), vsync, options.dev)
                : GlContext.headless(options.context.choice(options.dev, gui));
        try {
            options.size.checkGlLimits();
            Engine engine = new Engine(gl, shaders, settings, systems, options.size.width(), options.size.height());
            engine.world().setResource(new TimeOfDay(options.hours, daySpeed));
            return new Launch(gl, engine, options.dev, shaders);
        } catch (RuntimeException e) {
            gl.close();
            throw e;
        }
    }

    /**
     * Builds the world again from the current settings (the settings panel's "Rebuild world", after a change of a
     * setting read at start such as {@code terrain.relief}), with fresh systems on the same GL context, keeping the
     * camera, the clock and the size. The new engine is built before the old one is closed, so a failure (an
     * import file that does not exist) leaves the old world running and is thrown to the caller.
     */
    void rebuild() {
        Engine old = engine;
        Engine fresh = new Engine(gl, shaders, old.settings(), DemoScene.systems(), old.width(), old.height());
        fresh.world().setResource(old.world().resource(TimeOfDay.class));
        fresh.world().setResource(CameraDirection.class, old.world().findResource(CameraDirection.class)
                .orElse(CameraDirection.controls()).carriedOver(old.world().resource(Camera.class).pose()));
        old.close();
        engine = fresh;
    }

    /** The settings panel's view of this launch: the running engine's clock, and {@link #rebuild()}. */
    SettingsPanel.Host panelHost() {
        return new SettingsPanel.Host() {
            @Override
            public TimeOfDay time() {
                return engine.world().resource(TimeOfDay.class);
            }

            @Override
            public void setTime(TimeOfDay time) {
                engine.world().setResource(time);
            }

            @Override
            public void rebuild() {
                Launch.this.rebuild();
            }
        };
    }

    private static ShaderSources devShaders() {
        Path dir = Path.of("shaders");
        if (!Files.isDirectory(dir.resolve("common"))) {
            throw new UserError("--dev reads shaders from ./shaders, but " + dir.toAbsolutePath()
                    + " is not the repository's shaders folder: run from the repository root");
        }
        return ShaderSources.directory(dir);
    }

    @Override
    public void close() {
        engine.close();
        gl.close();
    }
}

package org.openworld.demo;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.core.SystemOrder;
import org.openworld.engine.elevation.ElevationImport;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.HeadlessChoice;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.terrain.heights.TerrainSettings;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code openworld info}: the OpenGL renderer and version, how the context was made, what every headless mode and
 * EGL device says on this machine, and the frame order; with {@code --set terrain.import-file=FILE} first the
 * imported map's extent, spacing and height range.
 */
@Command(name = "info", mixinStandardHelpOptions = true, description = "Print the OpenGL renderer, version and "
        + "context mode, what every headless mode says here, the EGL devices, and the resolved frame order; first the "
        + "imported map's extent, spacing and heights when --set names one.")
final class InfoCommand implements Callable<Integer> {

    @Mixin
    DevOption dev;

    @Option(names = "--frame", description = "Print only the resolved frame order (needs no OpenGL).")
    boolean frameOnly;

    @Option(names = "--set", paramLabel = "KEY=VALUE", description = "Change a setting, engine.* or terrain.* keys: "
            + "with terrain.import-file=FILE, print the map's extent, spacing and range first; repeatable.")
    List<String> set = new ArrayList<>();

    @Option(names = "--window", description = "Make the context with a window instead of headless.")
    boolean window;

    @Mixin
    ContextOptions context = new ContextOptions();

    @Override
    public Integer call() {
        printImport();
        if (!frameOnly) {
            HeadlessChoice choice = context.choice(false, false);
            try (GlContext gl = window ? GlContext.window("OpenWorld info", 320, 180, false)
                    : GlContext.headless(choice)) {
                System.out.println("renderer:  " + gl.renderer());
                System.out.println("vendor:    " + gl.vendor());
                System.out.println("version:   " + gl.version());
                String device = gl.device().isEmpty() ? "" : ", device " + gl.device();
                System.out.println("context:   " + gl.mode() + device);
                gl.tried().forEach(line -> System.out.println("  before it: " + line));
            }
            System.out.println();
            System.out.println("Headless modes, each tried on its own (the first that works is the default):");
            choice.survey().forEach(line -> System.out.println("  " + line));
            System.out.println("EGL devices (--gpu N):");
            HeadlessChoice.devices().forEach(line -> System.out.println("  " + line));
            System.out.println();
        }
        System.out.println("Frame order (the updates in this order; each pass draws in the order listed after):");
        System.out.print(SystemOrder.resolve(DemoScene.systems()).describe());
        return 0;
    }

    /** The imported map in one line, as {@code heightmap} and the start-up say it; nothing without an import. */
    private void printImport() {
        Settings settings = HeightmapCommand.newSettings();
        set.forEach(settings::apply);
        TerrainSettings terrain = settings.get(TerrainSettings.class);
        Path file = Path.of(terrain.importFile());
        if (!terrain.imports()) {
            return;
        }
        System.out.println("terrain:   " + file + (ElevationImport.handles(file)
                ? ": " + ElevationImport.describe(file, terrain, settings.get(EngineSettings.class).seed())
                : ": normalised to terrain.relief, " + terrain.spacing() + " m between samples"));
        System.out.println();
    }
}

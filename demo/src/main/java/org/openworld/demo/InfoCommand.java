package org.openworld.demo;

import java.util.concurrent.Callable;
import org.openworld.engine.core.SystemOrder;
import org.openworld.engine.gl.GlContext;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code openworld info}: the OpenGL renderer and version, how the context was made, and the frame order. */
@Command(name = "info", mixinStandardHelpOptions = true, description = "Print the OpenGL renderer, version and context mode, and the resolved frame order.")
final class InfoCommand implements Callable<Integer> {

    @Mixin
    DevOption dev;

    @Option(names = "--frame", description = "Print only the resolved frame order (needs no OpenGL).")
    boolean frameOnly;

    @Option(names = "--window", description = "Make the context with a window instead of headless.")
    boolean window;

    @Override
    public Integer call() {
        if (!frameOnly) {
            try (GlContext gl = window ? GlContext.window("OpenWorld info", 320, 180, false) : GlContext.headless()) {
                System.out.println("renderer:  " + gl.renderer());
                System.out.println("vendor:    " + gl.vendor());
                System.out.println("version:   " + gl.version());
                System.out.println("context:   " + gl.mode());
            }
            System.out.println();
        }
        System.out.println("Frame order (the updates in this order; each pass draws in the order listed after):");
        System.out.print(SystemOrder.resolve(DemoScene.systems()).describe());
        return 0;
    }
}

package org.openworld.demo;

import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;

/** {@code openworld run} (the default): the interactive window. */
@Command(name = "run", description = "Open the interactive window (the default command).")
final class RunCommand implements Callable<Integer> {

    @Mixin
    RenderOptions render;

    @Mixin
    PoseOptions pose;

    @Override
    public Integer call() throws Exception {
        var path = Poses.loadPath(pose);
        if (render.headless) {
            throw new UserError("run is interactive and needs a window; use 'shot' or 'bench' for headless rendering");
        }
        try (Launch launch = Launch.start(render, true, "OpenWorld")) {
            new WindowLoop(launch, path, pose).run();
        }
        return 0;
    }
}

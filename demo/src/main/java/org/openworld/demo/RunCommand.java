package org.openworld.demo;

import java.util.concurrent.Callable;
import org.openworld.engine.environment.TimeOfDay;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code openworld run} (the default): the interactive window. */
@Command(name = "run", mixinStandardHelpOptions = true, description = "Open the interactive window (the default command).")
final class RunCommand implements Callable<Integer> {

    @Mixin
    RenderOptions render;

    @Mixin
    PoseOptions pose;

    @Option(names = "--no-vsync", description = "Do not wait for the display's refresh (measure the uncapped frame rate).")
    boolean noVsync;

    @Override
    public Integer call() throws Exception {
        var path = Poses.loadPath(pose);
        if (render.headless) {
            throw new UserError("run is interactive and needs a window; use 'shot' or 'bench' for headless rendering");
        }
        try (Launch launch = Launch.start(render, true, !noVsync, "OpenWorld")) {
            launch.engine.world().setResource(new TimeOfDay(render.hours, render.daySpeed(DayCycle.RESUME_SPEED)));
            new WindowLoop(launch, path, pose).run();
        }
        return 0;
    }
}

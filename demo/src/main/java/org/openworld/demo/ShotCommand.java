package org.openworld.demo;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.gl.Image;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code openworld shot}: one image, headless by default. */
@Command(name = "shot", mixinStandardHelpOptions = true, description = "Render one image to a PNG file (headless unless --window).")
final class ShotCommand implements Callable<Integer> {

    @Mixin
    RenderOptions render;

    @Mixin
    PoseOptions pose;

    @Option(names = "--out", paramLabel = "FILE.png", required = true, description = "The PNG file to write.")
    Path out;

    @Override
    public Integer call() throws Exception {
        var path = Poses.loadPath(pose);
        long start = System.nanoTime();
        try (Launch launch = Launch.start(render, render.windowed(false), "OpenWorld shot")) {
            Camera camera = launch.engine.world().resource(Camera.class);
            launch.engine.update();
            camera.setPose(Poses.resolve(pose, path, launch.engine.world()));
            launch.engine.render();
            Image image = launch.engine.readImage();
            image.writePng(out);
            System.out.printf("wrote %s (%dx%d) in %.0f ms on %s, %s%n", out, image.width(), image.height(),
                    (System.nanoTime() - start) / 1e6, launch.gl.renderer(), launch.gl.mode());
        }
        return 0;
    }
}

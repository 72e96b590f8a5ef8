package org.openworld.demo;

import java.util.Locale;
import java.util.concurrent.Callable;
import org.openworld.engine.camera.CameraDirection;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.colour.ImageComparison;
import org.openworld.engine.gl.Image;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code openworld stability}: how much of the picture changes noticeably when the camera moves a little, the
 * figure of shimmer and crawl in motion. It renders the pose and the pose moved by {@code --move}, each exactly as
 * {@code shot} would (a fresh engine, one update, one frame), and prints the share of pixels whose CIEDE2000
 * difference exceeds 1 (just noticeable side by side), with the mean difference.
 *
 * <p>A sharp picture changes under any motion: 1 m at 400 m moves the far ground by about a fifth to half a pixel at
 * 480 × 270, and a well-filtered texture moved half a pixel changes by more than 1 wherever its contrast from pixel to
 * pixel exceeds 2. So the figure has a floor that no anti-aliasing removes (docs/benchmarks.md, "Temporal
 * stability", measures it with supersampled pictures); what lies above it is aliasing: edges that step, highlights
 * and texels that flicker.
 */
@Command(name = "stability", mixinStandardHelpOptions = true,
        description = "Share of pixels noticeably changed (CIEDE2000 above 1) between the pose and the pose moved a "
                + "little: shimmer in motion.")
final class StabilityCommand implements Callable<Integer> {

    @Mixin
    RenderOptions render;

    @Option(names = "--camera", paramLabel = "X,Y,Z,YAW,PITCH", required = true,
            converter = PoseOptions.PoseConverter.class,
            description = "The first frame's camera position (m) and direction (deg), as shot takes it.")
    CameraPose camera;

    @Option(names = "--move", paramLabel = "DX,DY,DZ", split = ",", defaultValue = "0,0,1",
            description = "How far the second frame's camera lies from the first, metres along x, y, z "
                    + "(default: ${DEFAULT-VALUE}, one metre south).")
    double[] move;

    @Override
    public Integer call() throws Exception {
        if (move.length != 3 || !(Double.isFinite(move[0]) && Double.isFinite(move[1]) && Double.isFinite(move[2]))) {
            throw new UserError("--move: expected three numbers of metres, dx,dy,dz (e.g. 0,0,1)");
        }
        CameraPose moved = new CameraPose(camera.x() + move[0], camera.y() + move[1], camera.z() + move[2],
                camera.yaw(), camera.pitch(), camera.fov());
        Image first = frame(camera);
        Image second = frame(moved);
        ImageComparison diff = ImageComparison.of(first, second);
        System.out.printf(Locale.ROOT, "stability at %dx%d, moved %s,%s,%s m: %.2f %% of the pixels noticeably "
                        + "changed (ΔE00 above 1), mean ΔE00 %.3f%n", first.width(), first.height(),
                num(move[0]), num(move[1]), num(move[2]), 100.0 * diff.pixelsAbove(1) / diff.pixels(),
                diff.meanDeltaE());
        return 0;
    }

    /** The picture {@code shot --camera pose} makes with these render options. */
    private Image frame(CameraPose pose) throws Exception {
        try (Launch launch = Launch.start(render, render.windowed(false), "OpenWorld stability")) {
            ShotCommand.prepare(launch, CameraDirection.fixed(pose));
            launch.engine.render();
            return ShotCommand.opaque(launch.engine.readImage());
        }
    }

    private static String num(double v) {
        return v == Math.rint(v) ? String.valueOf((long) v) : String.valueOf(v);
    }
}

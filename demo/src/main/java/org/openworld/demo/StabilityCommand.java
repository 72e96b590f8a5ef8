package org.openworld.demo;

import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.camera.CameraDirection;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.colour.Shimmer;
import org.openworld.engine.gl.Image;
import org.openworld.engine.settings.Settings;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code openworld stability}: how much of the picture changes noticeably when the camera moves a little, and how
 * much of that is shimmer. It renders the pose and the pose moved by {@code --move}, each exactly as {@code shot}
 * would (a fresh engine, one update, one frame), and prints the share of pixels whose CIEDE2000 difference exceeds 1
 * (just noticeable side by side), with the mean difference: the raw figure.
 *
 * <p>A sharp picture changes under any motion: 1 m at 400 m moves the far ground by about a fifth to half a pixel at
 * 480 × 270, and a well-filtered texture moved half a pixel changes by more than 1 wherever its contrast from pixel to
 * pixel exceeds 2, so the raw figure has a floor that no anti-aliasing removes. The command therefore renders both
 * poses again {@value #REFERENCE_SCALE} times larger on each side without {@code antialias.method}, reduces them to
 * the size ({@value #REFERENCE_SCALE}² samples a pixel) and prints the shimmer: the share of pixels whose change
 * exceeds their reference's by more than 1 ({@link Shimmer}, which says why this and not a reprojection), and the
 * frames' mean ΔE00 from their references (what anti-aliasing costs in sharpness or gains in fidelity).
 */
@Command(name = "stability", mixinStandardHelpOptions = true,
        description = "Share of pixels noticeably changed (CIEDE2000 above 1) between the pose and the pose moved a "
                + "little, and the share changed noticeably more than in supersampled references: shimmer in motion.")
final class StabilityCommand implements Callable<Integer> {

    /**
     * How many times larger on each side the references are drawn: 16 samples a pixel, where the raw figure of
     * supersampled pairs had converged (4 and 16 samples gave 12.8 and 12.9 % at 480 × 270; docs/benchmarks.md,
     * "Temporal stability").
     */
    static final int REFERENCE_SCALE = 4;

    /**
     * The references are supersampled, not post-filtered: the measure's zero is 16 plain samples a pixel, drawn at
     * render scale 1 whatever the frame's (a frame drawn at 0.65 or 2 is measured against the same 16 samples). The
     * terrain's level of detail, chosen by its error in the scene target's pixels, is scaled with them (by the
     * reference's pixels per scene pixel of the frame), so that a reference draws the same triangles as the frame
     * and differs only in its samples (the setting's largest value caps it).
     */
    private static final String REFERENCE_AA = "antialias.method=off";
    private static final String REFERENCE_SCALE_ONE = "engine.render-scale=1";
    private static final String LOD_ERROR = "lod.pixel-error";
    private static final double LOD_ERROR_MAX = 100;

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
        Shimmer shimmer = measure(render, camera, moved);
        System.out.printf(Locale.ROOT, "stability at %dx%d, moved %s,%s,%s m: %.2f %% of the pixels noticeably "
                        + "changed (ΔE00 above 1); shimmer: %.2f %% changed noticeably more than in their %d-sample "
                        + "references (ΔE00 above the reference's + 1); frames from their references: mean ΔE00 %.3f%n",
                render.size.width(), render.size.height(), num(move[0]), num(move[1]), num(move[2]),
                100 * shimmer.rawShare(), 100 * shimmer.share(), REFERENCE_SCALE * REFERENCE_SCALE,
                shimmer.meanError());
        return 0;
    }

    /** The two poses' frames with these options, measured against their references ({@link #reference}). */
    static Shimmer measure(RenderOptions render, CameraPose first, CameraPose second) {
        RenderOptions large = reference(render);
        return Shimmer.of(frame(render, first), frame(render, second), Shimmer.reduce(frame(large, first),
                REFERENCE_SCALE), Shimmer.reduce(frame(large, second), REFERENCE_SCALE));
    }

    /**
     * The options of the references: {@value #REFERENCE_SCALE} times the size, without anti-aliasing, at render
     * scale 1, the terrain's pixel error {@value #REFERENCE_SCALE} / the frame's render scale times as many pixels.
     */
    static RenderOptions reference(RenderOptions render) {
        Settings settings = Launch.settings(render);
        double error = Double.parseDouble(settings.text(LOD_ERROR));
        double scale = settings.get(EngineSettings.class).renderScale();
        return render.resized(new Size(render.size.width() * REFERENCE_SCALE,
                render.size.height() * REFERENCE_SCALE), List.of(REFERENCE_AA, REFERENCE_SCALE_ONE,
                LOD_ERROR + "=" + Math.min(LOD_ERROR_MAX, error * REFERENCE_SCALE / scale)));
    }

    /** The picture {@code shot --camera pose} makes with these render options. */
    static Image frame(RenderOptions options, CameraPose pose) {
        try (Launch launch = Launch.start(options, options.windowed(false), "OpenWorld stability")) {
            ShotCommand.prepare(launch, CameraDirection.fixed(pose));
            ShotCommand.renderSettled(launch);
            return ShotCommand.opaque(launch.engine.readImage());
        }
    }

    private static String num(double v) {
        return v == Math.rint(v) ? String.valueOf((long) v) : String.valueOf(v);
    }
}

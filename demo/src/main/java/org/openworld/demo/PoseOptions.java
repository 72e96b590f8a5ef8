package org.openworld.demo;

import java.nio.file.Path;
import java.util.Optional;
import org.openworld.engine.camera.CameraPose;
import picocli.CommandLine.Option;

/** Where to look from: {@code --camera x,y,z,yaw,pitch} or a moment of a camera path ({@code --path P --at S}). */
final class PoseOptions {

    @Option(names = "--camera", paramLabel = "X,Y,Z,YAW,PITCH", converter = PoseConverter.class,
            description = "Camera position (m; y above sea level) and direction (deg; yaw clockwise from north, pitch up).")
    CameraPose camera;

    @Option(names = "--path", paramLabel = "FILE", description = "A camera path (docs/camera-paths.md).")
    Path path;

    @Option(names = "--at", paramLabel = "SECONDS", description = "The moment of --path to show (default: 0).")
    Double at;

    /** The moment of {@code --path} to start from: {@code --at}, else 0 (checked by {@link Poses#loadPath}). */
    double at() {
        return at == null ? 0 : at;
    }

    Optional<CameraPose> explicitPose() {
        return Optional.ofNullable(camera);
    }

    static final class PoseConverter implements picocli.CommandLine.ITypeConverter<CameraPose> {
        /** The five fields in order, as the error messages name them. */
        private static final String[] FIELDS = {"x", "y", "z", "yaw", "pitch"};
        private static final String EXAMPLE = "0,120,400,0,-10";

        @Override
        public CameraPose convert(String text) {
            String[] parts = text.split(",", -1);
            if (parts.length != FIELDS.length) {
                throw new picocli.CommandLine.TypeConversionException("'" + text + "': " + parts.length
                        + " fields, expected x,y,z,yaw,pitch (metres and degrees), e.g. " + EXAMPLE);
            }
            double[] v = new double[FIELDS.length];
            for (int i = 0; i < FIELDS.length; i++) {
                String field = parts[i].trim();
                try {
                    v[i] = Double.parseDouble(field);
                } catch (NumberFormatException e) {
                    v[i] = Double.NaN;
                }
                if (!Double.isFinite(v[i])) {
                    throw new picocli.CommandLine.TypeConversionException("'" + text + "': " + FIELDS[i] + " is '"
                            + field + "', expected a number of " + (i < 3 ? "metres" : "degrees")
                            + " (x,y,z,yaw,pitch, e.g. " + EXAMPLE + ")");
                }
            }
            for (int i = 0; i < 3; i++) {
                if (!CameraPose.drawable(v[i])) {
                    throw new picocli.CommandLine.TypeConversionException("'" + text + "': " + FIELDS[i] + " is "
                            + parts[i].trim() + " m, beyond the renderer's reach: expected -16777216 .. 16777216 m "
                            + "(2^24 m from the origin, where the CPU's float positions are 1 m apart)");
                }
            }
            if (v[4] < -89 || v[4] > 89) {
                throw new picocli.CommandLine.TypeConversionException("'" + text + "': pitch must be within -89..89 degrees");
            }
            double yaw = ((v[3] % 360) + 360) % 360;
            return new CameraPose(v[0], v[1], v[2], yaw, v[4], CameraPose.DEFAULT_FOV);
        }
    }
}

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

    @Option(names = "--at", paramLabel = "SECONDS", description = "The moment of --path to show (default: ${DEFAULT-VALUE}).",
            defaultValue = "0")
    double at;

    Optional<CameraPose> explicitPose() {
        return Optional.ofNullable(camera);
    }

    static final class PoseConverter implements picocli.CommandLine.ITypeConverter<CameraPose> {
        @Override
        public CameraPose convert(String text) {
            String[] parts = text.split(",");
            String expected = "'" + text + "': expected x,y,z,yaw,pitch (metres and degrees), e.g. 0,120,400,0,-10";
            if (parts.length != 5) {
                throw new picocli.CommandLine.TypeConversionException(expected);
            }
            double[] v = new double[5];
            for (int i = 0; i < 5; i++) {
                try {
                    v[i] = Double.parseDouble(parts[i].trim());
                } catch (NumberFormatException e) {
                    throw new picocli.CommandLine.TypeConversionException(expected);
                }
                if (!Double.isFinite(v[i])) {
                    throw new picocli.CommandLine.TypeConversionException(expected);
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

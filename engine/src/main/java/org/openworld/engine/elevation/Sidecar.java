package org.openworld.engine.elevation;

import com.google.gson.Gson;
import com.google.gson.JsonParseException;
import java.awt.image.BufferedImage;
import java.awt.image.Raster;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import javax.imageio.ImageIO;
import org.openworld.engine.terrain.heights.HeightImportException;

/**
 * A 16-bit grayscale PNG or raw little-endian float32 elevation model with its scale in a JSON sidecar: the file's
 * name with {@code .json} in place of its extension ({@code dem.png} and {@code dem.json}), for example
 * <pre>{"width": 301, "height": 217, "spacing": 30, "verticalScale": 0.1, "verticalOffset": -200}</pre>
 * {@code width} and {@code height} in samples (a raw file only: its length gives their product, not the pair; a PNG
 * has its own), {@code spacing} in metres (or {@code spacingX} and {@code spacingZ}), height = stored value ·
 * {@code verticalScale} + {@code verticalOffset} metres (1 and 0 when left out; a 16-bit PNG at 0.1 m per level spans
 * 6553.5 m), and an optional {@code noData} stored value.
 */
final class Sidecar {

    /** The sidecar's fields; absent numbers are null. */
    record Fields(Integer width, Integer height, Double spacing, Double spacingX, Double spacingZ,
                  Double verticalScale, Double verticalOffset, Double noData) {
    }

    private Sidecar() {
    }

    /** The sidecar of {@code file}, if there is one. */
    static Optional<Path> of(Path file) {
        String name = file.getFileName().toString();
        Path sidecar = file.resolveSibling(name.substring(0, name.lastIndexOf('.')) + ".json");
        return Files.isRegularFile(sidecar) ? Optional.of(sidecar) : Optional.empty();
    }

    /** Reads the model {@code file} scaled by its sidecar. */
    static ElevationGrid read(Path file, Path sidecar, boolean png, long heapBytes) throws IOException {
        Fields f;
        try {
            f = new Gson().fromJson(Files.readString(sidecar), Fields.class);
        } catch (JsonParseException e) {
            throw new HeightImportException(sidecar + ": not a JSON object of numbers: " + e.getMessage());
        }
        Double sx = f.spacingX() != null ? f.spacingX() : f.spacing();
        Double sz = f.spacingZ() != null ? f.spacingZ() : f.spacing();
        if (sx == null || sz == null || !(sx > 0 && sz > 0)) {
            throw new HeightImportException(sidecar + ": needs \"spacing\" (or \"spacingX\" and \"spacingZ\"), "
                    + "metres between samples, greater than 0");
        }
        float[] stored;
        int w;
        int h;
        if (png) {
            BufferedImage image = ImageIO.read(file.toFile());
            if (image == null) {
                throw new HeightImportException(file + ": not a readable PNG");
            }
            Raster raster = image.getRaster();
            if (raster.getNumBands() != 1 || raster.getSampleModel().getSampleSize(0) != 16) {
                throw new HeightImportException(file + ": is not a 16-bit grayscale PNG (" + raster.getNumBands()
                        + " band(s) of " + raster.getSampleModel().getSampleSize(0) + " bits)");
            }
            w = raster.getWidth();
            h = raster.getHeight();
            ElevationImport.checkHeap(file, w, h, heapBytes);
            stored = raster.getSamples(0, 0, w, h, 0, (float[]) null);
        } else {
            if (f.width() == null || f.height() == null || f.width() < 2 || f.height() < 2) {
                throw new HeightImportException(sidecar + ": needs \"width\" and \"height\" of the raw file, samples, "
                        + "at least 2 each");
            }
            w = f.width();
            h = f.height();
            ElevationImport.checkHeap(file, w, h, heapBytes);
            long expected = (long) w * h * Float.BYTES;
            if (Files.size(file) != expected) {
                throw new HeightImportException(file + ": is " + Files.size(file) + " bytes; " + sidecar.getFileName()
                        + " says " + w + "×" + h + " float32 samples, " + expected + " bytes");
            }
            stored = new float[w * h];
            ByteBuffer.wrap(Files.readAllBytes(file)).order(ByteOrder.LITTLE_ENDIAN).asFloatBuffer().get(stored);
        }
        double scale = f.verticalScale() == null ? 1 : f.verticalScale();
        double offset = f.verticalOffset() == null ? 0 : f.verticalOffset();
        for (int i = 0; i < stored.length; i++) {
            boolean missing = !Float.isFinite(stored[i]) || f.noData() != null && stored[i] == f.noData().floatValue();
            stored[i] = missing ? Float.NaN : (float) (stored[i] * scale + offset);
        }
        return new ElevationGrid(w, h, sx, sz, stored, Double.NaN, true);
    }
}

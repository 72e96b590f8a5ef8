package org.openworld.engine.elevation;

import com.twelvemonkeys.imageio.metadata.Entry;
import com.twelvemonkeys.imageio.metadata.tiff.TIFF;
import com.twelvemonkeys.imageio.metadata.tiff.TIFFEntry;
import com.twelvemonkeys.imageio.plugins.tiff.TIFFImageMetadata;
import com.twelvemonkeys.imageio.plugins.tiff.TIFFImageWriterSpi;
import java.awt.Transparency;
import java.awt.color.ColorSpace;
import java.awt.image.BufferedImage;
import java.awt.image.ColorModel;
import java.awt.image.ComponentColorModel;
import java.awt.image.DataBuffer;
import java.awt.image.WritableRaster;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriter;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.plugins.tiff.BaselineTIFFTagSet;
import javax.imageio.plugins.tiff.GeoTIFFTagSet;
import javax.imageio.plugins.tiff.TIFFDirectory;
import javax.imageio.plugins.tiff.TIFFField;
import javax.imageio.plugins.tiff.TIFFTag;
import javax.imageio.plugins.tiff.TIFFTagSet;
import javax.imageio.stream.ImageOutputStream;

/**
 * Writes elevation files for the tests with real writers: 16-bit GeoTIFFs with TwelveMonkeys' writer, float32
 * GeoTIFFs with the JDK's own TIFF writer (TwelveMonkeys' writer has no floating-point samples), PNGs with ImageIO,
 * and the JSON sidecars.
 */
final class ElevationFiles {

    /** GeoKeys: a projected model in metres, or a geographic one in degrees (WGS 84). */
    static final int[] PROJECTED_METRES = {1, 1, 0, 2, 1024, 0, 1, 1, 3076, 0, 1, 9001};
    static final int[] PROJECTED_FEET = {1, 1, 0, 2, 1024, 0, 1, 1, 3076, 0, 1, 9002};
    static final int[] GEOGRAPHIC = {1, 1, 0, 2, 1024, 0, 1, 2, 2048, 0, 1, 4326};

    private ElevationFiles() {
    }

    /** A smooth relief with a few hundred metres of range: the test's ground truth at column x, row z. */
    static float relief(int x, int z) {
        return (float) (-150 + 400 * Math.sin(x * 0.031) * Math.cos(z * 0.043) + 0.9 * x + 0.4 * z);
    }

    static float[] reliefGrid(int w, int h) {
        float[] a = new float[w * h];
        for (int z = 0; z < h; z++) {
            for (int x = 0; x < w; x++) {
                a[z * w + x] = relief(x, z);
            }
        }
        return a;
    }

    /**
     * A one-band GeoTIFF of {@code type} samples (rounded for the integer types); scale, tiepoint, GeoKeys and no-data
     * tags only where given (null leaves them out).
     */
    static Path geoTiff(Path file, int w, int h, float[] values, int type, double[] scale, double[] tie, int[] keys,
                        String noData) throws IOException {
        ColorModel cm = new ComponentColorModel(ColorSpace.getInstance(ColorSpace.CS_GRAY), false, false,
                Transparency.OPAQUE, type);
        WritableRaster raster = cm.createCompatibleWritableRaster(w, h);
        for (int z = 0; z < h; z++) {
            for (int x = 0; x < w; x++) {
                float v = values[z * w + x];
                if (type == DataBuffer.TYPE_FLOAT) {
                    raster.setSample(x, z, 0, v);
                } else {
                    raster.setSample(x, z, 0, Math.round(v));
                }
            }
        }
        ImageWriter writer;
        IIOMetadata metadata;
        if (type == DataBuffer.TYPE_FLOAT) {
            writer = jdkTiffWriter();
            TIFFDirectory dir = new TIFFDirectory(new TIFFTagSet[] {BaselineTIFFTagSet.getInstance(),
                GeoTIFFTagSet.getInstance()}, null);
            GeoTIFFTagSet geo = GeoTIFFTagSet.getInstance();
            if (scale != null) {
                dir.addTIFFField(new TIFFField(geo.getTag(GeoTiff.MODEL_PIXEL_SCALE), TIFFTag.TIFF_DOUBLE, 3, scale));
                dir.addTIFFField(new TIFFField(geo.getTag(GeoTiff.MODEL_TIEPOINT), TIFFTag.TIFF_DOUBLE, 6, tie));
            }
            if (keys != null) {
                char[] k = new char[keys.length];
                for (int i = 0; i < keys.length; i++) {
                    k[i] = (char) keys[i];
                }
                dir.addTIFFField(new TIFFField(geo.getTag(GeoTiff.GEO_KEY_DIRECTORY), TIFFTag.TIFF_SHORT, k.length, k));
            }
            metadata = dir.getAsMetadata();
        } else {
            writer = new TIFFImageWriterSpi().createWriterInstance();
            List<Entry> entries = new ArrayList<>();
            if (scale != null) {
                entries.add(new TIFFEntry(GeoTiff.MODEL_PIXEL_SCALE, TIFF.TYPE_DOUBLE, scale));
                entries.add(new TIFFEntry(GeoTiff.MODEL_TIEPOINT, TIFF.TYPE_DOUBLE, tie));
            }
            if (keys != null) {
                short[] k = new short[keys.length];
                for (int i = 0; i < keys.length; i++) {
                    k[i] = (short) keys[i];
                }
                entries.add(new TIFFEntry(GeoTiff.GEO_KEY_DIRECTORY, TIFF.TYPE_SHORT, k));
            }
            if (noData != null) {
                entries.add(new TIFFEntry(GeoTiff.GDAL_NODATA, TIFF.TYPE_ASCII, noData));
            }
            metadata = new TIFFImageMetadata(entries);
        }
        try (ImageOutputStream out = ImageIO.createImageOutputStream(file.toFile())) {
            writer.setOutput(out);
            writer.write(null, new IIOImage(new BufferedImage(cm, raster, false, null), null, metadata), null);
        } finally {
            writer.dispose();
        }
        return file;
    }

    /** The JDK's TIFF writer (javax.imageio's own plugin), not TwelveMonkeys'. */
    private static ImageWriter jdkTiffWriter() {
        var writers = ImageIO.getImageWritersByFormatName("tiff");
        while (writers.hasNext()) {
            ImageWriter w = writers.next();
            if (w.getClass().getName().startsWith("com.sun.imageio")) {
                return w;
            }
        }
        throw new IllegalStateException("the JDK's TIFF writer is missing");
    }

    /** A 16-bit grayscale PNG of stored values (0 .. 65535). */
    static Path png16(Path file, int w, int h, int[] stored) throws IOException {
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_USHORT_GRAY);
        image.getRaster().setSamples(0, 0, w, h, 0, stored);
        ImageIO.write(image, "png", file.toFile());
        return file;
    }

    /** Raw little-endian float32 samples, row by row. */
    static Path raw(Path file, float[] values) throws IOException {
        ByteBuffer bytes = ByteBuffer.allocate(values.length * Float.BYTES).order(ByteOrder.LITTLE_ENDIAN);
        bytes.asFloatBuffer().put(values);
        Files.write(file, bytes.array());
        return file;
    }

    /** A sidecar: {@code "key": value} pairs, values already JSON. */
    static void sidecar(Path file, String... pairs) throws IOException {
        String name = file.getFileName().toString();
        StringBuilder json = new StringBuilder("{");
        for (int i = 0; i < pairs.length; i += 2) {
            json.append(i > 0 ? ", " : "").append(String.format(Locale.ROOT, "\"%s\": %s", pairs[i], pairs[i + 1]));
        }
        Files.writeString(file.resolveSibling(name.substring(0, name.lastIndexOf('.')) + ".json"), json + "}");
    }
}

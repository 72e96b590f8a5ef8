package org.openworld.engine.elevation;

import com.twelvemonkeys.imageio.metadata.Entry;
import com.twelvemonkeys.imageio.plugins.tiff.TIFFImageMetadata;
import com.twelvemonkeys.imageio.plugins.tiff.TIFFImageReaderSpi;
import java.awt.image.DataBuffer;
import java.awt.image.Raster;
import java.io.IOException;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;
import org.openworld.engine.terrain.heights.HeightImportException;

/**
 * Reads a GeoTIFF elevation model with TwelveMonkeys' TIFF reader: one band of float32, float64, int16, uint16 or
 * int32 samples, and the GeoTIFF tags that place it.
 *
 * <ul>
 *   <li>ModelPixelScale (tag 33550): the pixel's size (sx, sy) in the model's units;</li>
 *   <li>ModelTiepoint (33922): pixel (i, j) at model (X, Y): with the scale, the latitude of the map's centre,
 *       {@code Y − sy · (rows/2 − j)};</li>
 *   <li>GeoKeyDirectory (34735): GTModelType (key 1024: 1 projected, 2 geographic), ProjLinearUnits (3076: 9001
 *       metre, 9002 foot, 9003 US survey foot) and VerticalUnits (4099, the same codes) turn both into metres;</li>
 *   <li>GDAL_NODATA (42113): the no-data value, as text; NaN samples are no-data too.</li>
 * </ul>
 * A geographic model's degrees become metres at the centre's latitude φ on the WGS 84 ellipsoid: a degree of
 * latitude is {@code π/180 · a(1 − e²)/(1 − e² sin²φ)^1.5}, a degree of longitude {@code π/180 · a cos φ /
 * (1 − e² sin²φ)^0.5} (111.0 km and 89.5 km at 36.6° N). The map is drawn flat with that one spacing: a map 1° tall
 * is off by the change of cos φ across it, 1.3 % at 36° N between its centre and its edge.
 */
final class GeoTiff {

    static final int MODEL_PIXEL_SCALE = 33550;
    static final int MODEL_TIEPOINT = 33922;
    static final int GEO_KEY_DIRECTORY = 34735;
    static final int GDAL_NODATA = 42113;

    private static final int KEY_MODEL_TYPE = 1024;
    private static final int KEY_LINEAR_UNITS = 3076;
    private static final int KEY_VERTICAL_UNITS = 4099;
    private static final int MODEL_GEOGRAPHIC = 2;

    /** WGS 84: semi-major axis, metres, and first eccentricity squared. */
    private static final double A = 6_378_137.0;
    private static final double E2 = 6.694_379_990_14e-3;

    private GeoTiff() {
    }

    /**
     * The model in {@code file}; {@code fallbackSpacing} metres apart and unscaled if it has no georeference and
     * {@code requireScale} is false.
     */
    static ElevationGrid read(Path file, boolean requireScale, double fallbackSpacing, long heapBytes) {
        ImageReader reader = null;
        try (ImageInputStream in = ImageIO.createImageInputStream(file.toFile())) {
            reader = new TIFFImageReaderSpi().createReaderInstance();
            reader.setInput(in);
            int w = reader.getWidth(0);
            int h = reader.getHeight(0);
            ElevationImport.checkHeap(file, w, h, heapBytes);
            TIFFImageMetadata tags = (TIFFImageMetadata) reader.getImageMetadata(0);
            double[] scale = doubles(tags.getTIFFField(MODEL_PIXEL_SCALE));
            double[] tie = doubles(tags.getTIFFField(MODEL_TIEPOINT));
            if (scale == null && requireScale) {
                throw new HeightImportException(file + ": has no georeference (no ModelPixelScale and ModelTiepoint "
                        + "tags), so its spacing is unknown: add them (gdal_translate -a_srs/-a_ullr), or set "
                        + "terrain.import-scale=false to normalise it at terrain.spacing");
            }
            Raster raster = reader.readRaster(0, null);
            float[] heights = samples(file, raster);
            if (scale == null) {
                return new ElevationGrid(w, h, fallbackSpacing, fallbackSpacing, heights, Double.NaN, false);
            }
            int[] keys = ints(tags.getTIFFField(GEO_KEY_DIRECTORY));
            double vertical = unit(file, key(keys, KEY_VERTICAL_UNITS), "VerticalUnits");
            noData(tags.getTIFFField(GDAL_NODATA), heights, vertical);
            if (key(keys, KEY_MODEL_TYPE) == MODEL_GEOGRAPHIC) {
                if (tie == null) {
                    throw new HeightImportException(file + ": is in degrees but has no ModelTiepoint tag, so its "
                            + "latitude, and with it the metres of a degree of longitude, is unknown");
                }
                double latitude = tie[4] - scale[1] * (h / 2.0 - tie[1]);
                double sin = Math.sin(Math.toRadians(latitude));
                double w2 = 1 - E2 * sin * sin;
                double perDegreeZ = Math.toRadians(A * (1 - E2) / Math.pow(w2, 1.5));
                double perDegreeX = Math.toRadians(A * Math.cos(Math.toRadians(latitude)) / Math.sqrt(w2));
                return new ElevationGrid(w, h, scale[0] * perDegreeX, scale[1] * perDegreeZ, heights, latitude, true);
            }
            double linear = unit(file, key(keys, KEY_LINEAR_UNITS), "ProjLinearUnits");
            return new ElevationGrid(w, h, scale[0] * linear, scale[1] * linear, heights, Double.NaN, true);
        } catch (IOException | RuntimeException e) {
            if (e instanceof HeightImportException known) {
                throw known;
            }
            throw new HeightImportException(file + ": not a readable TIFF: " + e.getMessage());
        } finally {
            if (reader != null) {
                reader.dispose();
            }
        }
    }

    /** One band of float or integer samples, as metres before the vertical unit. */
    private static float[] samples(Path file, Raster raster) {
        int type = raster.getDataBuffer().getDataType();
        int bits = raster.getSampleModel().getSampleSize(0);
        if (raster.getNumBands() != 1 || type == DataBuffer.TYPE_BYTE) {
            throw new HeightImportException(file + ": holds " + raster.getNumBands() + " band(s) of " + bits
                    + "-bit samples; an elevation model needs one band of float32, int16 or uint16 samples"
                    + (type == DataBuffer.TYPE_BYTE ? " (256 levels make visible terraces)" : ""));
        }
        return raster.getSamples(0, 0, raster.getWidth(), raster.getHeight(), 0, (float[]) null);
    }

    /** Marks the no-data samples NaN and scales the rest by the vertical unit. */
    private static void noData(Entry tag, float[] heights, double vertical) {
        double missing = tag == null ? Double.NaN : Double.parseDouble(tag.getValueAsString().trim());
        for (int i = 0; i < heights.length; i++) {
            heights[i] = heights[i] == (float) missing ? Float.NaN : (float) (heights[i] * vertical);
        }
    }

    /** Metres per unit of an EPSG unit code; 1 when the key is absent. */
    private static double unit(Path file, int code, String key) {
        return switch (code) {
            case -1, 9001 -> 1;
            case 9002 -> 0.3048;
            case 9003 -> 1200.0 / 3937;
            default -> throw new HeightImportException(file + ": GeoKey " + key + " is unit " + code
                    + "; expected 9001 (metre), 9002 (foot) or 9003 (US survey foot)");
        };
    }

    /** A GeoKey's inline value (its tag location 0), or −1 when absent. */
    private static int key(int[] directory, int id) {
        if (directory == null) {
            return -1;
        }
        for (int k = 4; k + 3 < directory.length; k += 4) {
            if (directory[k] == id && directory[k + 1] == 0) {
                return directory[k + 3];
            }
        }
        return -1;
    }

    private static double[] doubles(Entry tag) {
        if (tag == null) {
            return null;
        }
        Object v = tag.getValue();
        if (v instanceof double[] d) {
            return d;
        }
        throw new IllegalArgumentException("tag " + tag.getFieldName() + " holds " + v.getClass().getSimpleName()
                + ", not doubles");
    }

    private static int[] ints(Entry tag) {
        if (tag == null) {
            return null;
        }
        Object v = tag.getValue();
        if (v instanceof int[] i) {
            return i;
        }
        if (v instanceof short[] s) {
            int[] i = new int[s.length];
            for (int k = 0; k < s.length; k++) {
                i[k] = Short.toUnsignedInt(s[k]);
            }
            return i;
        }
        return null;
    }
}

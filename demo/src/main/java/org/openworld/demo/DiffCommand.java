package org.openworld.demo;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.openworld.engine.colour.ImageComparison;
import org.openworld.engine.gl.Image;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code openworld diff A.png B.png [--out D.png]}: how two pictures differ, to the eye. It prints the size, the
 * changed pixels (any channel different), the pixels whose colour differs noticeably, the mean and the largest
 * colour difference and where the largest is; {@code --out} draws where they differ ({@link
 * ImageComparison#differenceImage}: the first picture in grey, a faint red cast where the change is below
 * {@code --threshold}, red to yellow where it is noticeable).
 *
 * <p>The colour difference is CIEDE2000 (ΔE00, {@link org.openworld.engine.colour.DeltaE}) on colours converted
 * from sRGB to CIELAB (D65): about 1 is just noticeable between flat patches side by side, 2 to 3 is seen at a glance.
 * The pictures are read with stb_image (PNG, JPEG, BMP, TGA...), without OpenGL.
 *
 * <p>Exit code 0 whenever the comparison was made, the verdict ("identical" or "differ") is printed; unlike
 * {@code cmp}, 1 stays "a failure inside the program" as for every {@code openworld} command. A missing or
 * unreadable file, or two sizes, is a user's mistake: exit code 2 with one line.
 */
@Command(name = "diff", mixinStandardHelpOptions = true,
        description = "Compare two pictures of one size: changed pixels, the mean and largest colour difference "
                + "(CIEDE2000, ΔE00; about 1 is just noticeable) and where; --out draws where they differ. No OpenGL.")
final class DiffCommand implements Callable<Integer> {

    @Mixin
    DevOption dev;

    @Parameters(index = "0", paramLabel = "A.png", description = "The first picture (the reference).")
    Path first;

    @Parameters(index = "1", paramLabel = "B.png", description = "The second picture, of the same size.")
    Path second;

    @Option(names = "--out", paramLabel = "D.png",
            description = "Write a difference image (PNG, or JPEG for a .jpg name; never one of the inputs): A in grey at half brightness, each changed pixel from red "
                    + "(the smallest difference) to yellow (the largest).")
    Path out;

    @Option(names = "--force", description = "Overwrite --out even if it is a file other than a PNG.")
    boolean force;

    @Option(names = "--threshold", paramLabel = "DE", defaultValue = "1",
            description = "A pixel is noticeably different above this ΔE00 (default: ${DEFAULT-VALUE}, just "
                    + "noticeable side by side).")
    double threshold;

    @Override
    public Integer call() throws IOException {
        if (!(threshold >= 0)) {
            throw new UserError("--threshold " + threshold + ": expected a colour difference of 0 or more");
        }
        if (out != null) {
            Outputs.picture(out, force);
            Outputs.notAnInput(out, first, second);
        }
        Image a = read(first);
        Image b = read(second);
        if (a.width() != b.width() || a.height() != b.height()) {
            throw new UserError("the pictures differ in size: " + first + " is " + a.width() + "x" + a.height()
                    + ", " + second + " is " + b.width() + "x" + b.height());
        }
        ImageComparison diff = ImageComparison.of(a, b);
        int pixels = diff.pixels();
        int noticeable = diff.pixelsAbove(threshold);
        System.out.printf(Locale.ROOT, "%s and %s: %dx%d, %s%n", first, second, diff.width(), diff.height(),
                diff.changedPixels() == 0 ? "identical" : "they differ");
        System.out.printf(Locale.ROOT, "changed:     %d of %d pixels (%.3f %%), any channel different%n",
                diff.changedPixels(), pixels, percent(diff.changedPixels(), pixels));
        System.out.printf(Locale.ROOT, "noticeable:  %d pixels (%.3f %%), ΔE00 above %s%n", noticeable,
                percent(noticeable, pixels), threshold);
        System.out.printf(Locale.ROOT, "mean ΔE00:   %.4f over all pixels%n", diff.meanDeltaE());
        System.out.printf(Locale.ROOT, "max ΔE00:    %.4f at (%d, %d), x from the left, y from the top%n",
                diff.maxDeltaE(), diff.maxX(), diff.maxY());
        if (out != null) {
            diff.differenceImage(threshold).write(out);
            System.out.println("wrote " + out + ": grey where equal, a faint red cast where changed by ΔE00 "
                    + threshold + " or less, red to yellow (ΔE00 " + String.format(Locale.ROOT, "%.4f",
                    diff.maxDeltaE()) + ") where noticeable");
        }
        return 0;
    }

    /** Reads a picture, or stops with one line naming the file and why it cannot be read. */
    private static Image read(Path file) {
        if (Files.isDirectory(file)) {
            throw new UserError(file + ": is a folder, expected a picture");
        }
        try {
            return Image.read(file);
        } catch (NoSuchFileException e) {
            throw new UserError(file + ": no such file");
        } catch (AccessDeniedException e) {
            throw new UserError(file + ": permission denied");
        } catch (IOException e) {
            throw new UserError(e.getMessage());
        }
    }

    private static double percent(int count, int of) {
        return 100.0 * count / of;
    }
}

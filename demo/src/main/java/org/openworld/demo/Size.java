package org.openworld.demo;

import picocli.CommandLine;
import picocli.CommandLine.ITypeConverter;

/** A render size in pixels, written WxH on the command line. */
record Size(int width, int height) {

    /** Largest side accepted, pixels (GL_MAX_TEXTURE_SIZE on most hardware is 16384). */
    static final int MAX_SIDE = 16384;

    static final class Converter implements ITypeConverter<Size> {
        @Override
        public Size convert(String text) {
            String[] parts = text.toLowerCase(java.util.Locale.ROOT).split("x");
            try {
                if (parts.length == 2) {
                    int w = Integer.parseInt(parts[0].trim());
                    int h = Integer.parseInt(parts[1].trim());
                    if (w >= 1 && h >= 1 && w <= MAX_SIDE && h <= MAX_SIDE) {
                        return new Size(w, h);
                    }
                }
            } catch (NumberFormatException e) {
                // fall through to the message below
            }
            throw new CommandLine.TypeConversionException("'" + text + "': expected WIDTHxHEIGHT in pixels, each 1.."
                    + MAX_SIDE + ", e.g. 1280x720");
        }
    }
}

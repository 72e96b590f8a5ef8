package org.openworld.engine.settings;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.failure.UserFacing;

/**
 * A file the user wrote by hand (a settings file, a camera path, a benchmark summary) read as text: UTF-8, with a
 * leading byte order mark skipped (editors on Windows write one, and it would otherwise stick to the first word as an
 * invisible U+FEFF), and a file that is not text refused with the first byte that is not, and where it is.
 *
 * <p>The JDK's {@code Files.readString} reports malformed UTF-8 as "Input length = 1", which names neither the file's
 * problem nor the place; a {@link CharsetDecoder} set to {@link CodingErrorAction#REPORT} stops at the bad byte, and
 * its input position is the offset. A NUL byte is valid UTF-8 but appears in no text file, so it is refused too: it
 * catches a binary file (an image, a compressed file) that happens to start with valid sequences.
 *
 * <p>Cost: one pass over the bytes; the whole file is held twice (bytes and characters), fine for hand-written files.
 */
public final class TextFile {

    /** The UTF-8 encoding of U+FEFF, the byte order mark. */
    private static final byte[] BOM = {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF};

    private TextFile() {
    }

    /**
     * The bytes are not UTF-8 text; the message is {@code not a text file: byte 0x.. at offset N}. Each reader puts
     * the file's name before it, in its own error type.
     */
    public static final class NotTextException extends IOException implements UserFacing {
        private final long offset;

        NotTextException(int value, long offset) {
            super(String.format(Locale.ROOT, "not a text file: byte 0x%02x at offset %d", value & 0xFF, offset));
            this.offset = offset;
        }

        @Override
        public ExitCode exitCode() {
            return ExitCode.USER_MISTAKE;
        }

        /** The 0-based offset in the file of the first byte that is not text. */
        public long offset() {
            return offset;
        }
    }

    /**
     * Reads {@code file} as UTF-8 text, without a leading byte order mark.
     *
     * @throws NotTextException if the bytes are not UTF-8 text
     * @throws IOException      if the file cannot be read (the JDK's exception, e.g. {@code NoSuchFileException})
     */
    public static String read(Path file) throws IOException {
        return decode(Files.readAllBytes(file));
    }

    /** Decodes UTF-8 text, as {@link #read(Path)}. */
    public static String decode(byte[] bytes) throws NotTextException {
        int start = startsWithBom(bytes) ? BOM.length : 0;
        for (int i = start; i < bytes.length; i++) {
            if (bytes[i] == 0) {
                throw new NotTextException(0, i);
            }
        }
        CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes, start, bytes.length - start);
        CharBuffer out = CharBuffer.allocate(bytes.length - start);
        CoderResult result = decoder.decode(in, out, true);
        if (!result.isError()) {
            result = decoder.flush(out);
        }
        if (result.isError()) {
            throw new NotTextException(bytes[in.position()], in.position());
        }
        return out.flip().toString();
    }

    private static boolean startsWithBom(byte[] bytes) {
        return bytes.length >= BOM.length && bytes[0] == BOM[0] && bytes[1] == BOM[1] && bytes[2] == BOM[2];
    }
}

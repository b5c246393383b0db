package dempano.io;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.FloatBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

/** Float32 rasters as NumPy {@code .npy} (row 0 first) or {@code .pfm} (bottom row first, as the format requires). */
public final class FloatArrayWriter {
    private FloatArrayWriter() {
    }

    /** NPY v1.0, little-endian float32, shape (rows, cols), C order; written atomically. */
    public static void writeNpy(Path file, FloatBuffer data, int rows, int cols) throws IOException {
        AtomicFiles.write(file, npy(data, rows, cols));
    }

    /** PFM (see {@link #pfm}); written atomically. */
    public static void writePfm(Path file, FloatBuffer data, int rows, int cols) throws IOException {
        AtomicFiles.write(file, pfm(data, rows, cols));
    }

    /** The bytes of an NPY v1.0 file: little-endian float32, shape (rows, cols), C order. */
    public static AtomicFiles.Body npy(FloatBuffer data, int rows, int cols) {
        check(data, rows, cols);
        String dict = "{'descr': '<f4', 'fortran_order': False, 'shape': (" + rows + ", " + cols + "), }";
        int preamble = 10; // magic (6) + version (2) + header length (2)
        int total = preamble + dict.length() + 1;
        int pad = (64 - total % 64) % 64;
        String header = dict + " ".repeat(pad) + "\n";
        return out -> {
            out.write(new byte[] {(byte) 0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0});
            out.write(header.length() & 0xff);
            out.write((header.length() >> 8) & 0xff);
            out.write(header.getBytes(StandardCharsets.US_ASCII));
            writeRows(out, data, rows, cols, false);
        };
    }

    /** The bytes of a portable float map, little-endian (scale −1), rows bottom to top. */
    public static AtomicFiles.Body pfm(FloatBuffer data, int rows, int cols) {
        check(data, rows, cols);
        return out -> {
            out.write(("Pf\n" + cols + " " + rows + "\n-1.0\n").getBytes(StandardCharsets.US_ASCII));
            writeRows(out, data, rows, cols, true);
        };
    }

    private static void check(FloatBuffer data, int rows, int cols) {
        if (data.remaining() != (long) rows * cols) {
            throw new IllegalArgumentException("data has " + data.remaining() + " values, not " + rows + "×" + cols);
        }
    }

    private static void writeRows(java.io.OutputStream out, FloatBuffer data, int rows, int cols, boolean bottomUp)
            throws IOException {
        ByteBuffer row = ByteBuffer.allocate(cols * 4).order(ByteOrder.LITTLE_ENDIAN);
        int base = data.position();
        for (int i = 0; i < rows; i++) {
            int r = bottomUp ? rows - 1 - i : i;
            row.clear();
            for (int c = 0; c < cols; c++) {
                row.putFloat(data.get(base + r * cols + c));
            }
            out.write(row.array());
        }
    }
}

package dempano.dem;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.IntBinaryOperator;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;

/** Writes synthetic .hgt files whose every sample is known (row 0 north, big-endian int16). */
final class HgtTestFiles {
    private HgtTestFiles() {
    }

    static byte[] bytes(int n, IntBinaryOperator heightOfRowCol) {
        ByteBuffer b = ByteBuffer.allocate(2 * n * n);
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                b.putShort((short) heightOfRowCol.applyAsInt(r, c));
            }
        }
        return b.array();
    }

    static Path write(Path dir, String name, byte[] bytes) throws IOException {
        Path p = dir.resolve(name);
        Files.write(p, bytes);
        return p;
    }

    static Path zip(Path dir, String zipName, String... entriesAndContent) throws IOException {
        Path p = dir.resolve(zipName);
        try (OutputStream out = Files.newOutputStream(p); ZipOutputStream z = new ZipOutputStream(out)) {
            for (int i = 0; i < entriesAndContent.length; i += 2) {
                z.putNextEntry(new ZipEntry(entriesAndContent[i]));
                z.write(Files.readAllBytes(Path.of(entriesAndContent[i + 1])));
                z.closeEntry();
            }
        }
        return p;
    }
}

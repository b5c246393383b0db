package dempano.dem;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.zip.ZipEntry;
import java.util.zip.ZipException;
import java.util.zip.ZipFile;

/**
 * Reads SRTM {@code .hgt} tiles: big-endian int16 heights in metres, row 0 the northern edge,
 * -32768 for voids; 1201² samples (SRTM3) or 3601² (SRTM1), told apart by the length. Also
 * {@code .hgt.zip} holding one {@code .hgt}, or a {@code .hgt.gz}. The tile's position comes from the file name.
 */
public final class HgtReader {
    /** The void marker in SRTM files. */
    public static final short VOID = Short.MIN_VALUE;
    /** Heights outside this range (voids aside) mean a corrupt or little-endian file. */
    static final int MIN_PLAUSIBLE_METRES = -1000, MAX_PLAUSIBLE_METRES = 9000;

    private HgtReader() {
    }

    /**
     * Reads and void-fills a tile with the default fill ({@link VoidFill#DEFAULT}).
     *
     * @throws DemException naming the file and the problem (bad name, size, zip content, heights, I/O)
     */
    public static HgtTile read(Path file) {
        return read(file, VoidFill.DEFAULT);
    }

    /**
     * Reads a tile and fills its voids with the given method.
     *
     * @throws DemException naming the file and the problem (bad name, size, zip content, heights, I/O)
     */
    public static HgtTile read(Path file, VoidFill fill) {
        String fileName = file.getFileName().toString();
        TileId id = TileId.parseFileName(fileName);
        byte[] bytes;
        try {
            String lower = fileName.toLowerCase(java.util.Locale.ROOT);
            bytes = lower.endsWith(".zip") ? unzip(file, id) : lower.endsWith(".gz") ? gunzip(file) : Files.readAllBytes(file);
        } catch (NoSuchFileException e) {
            throw new DemException(file + ": no such file", e);
        } catch (ZipException e) {
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("bad compression method: (\\d+)")
                    .matcher(String.valueOf(e.getMessage()));
            if (m.find()) {
                int method = Integer.parseInt(m.group(1));
                throw new DemException(file + " is compressed with zip method " + method
                        + (ZIP_METHODS.containsKey(method) ? " (" + ZIP_METHODS.get(method) + ")" : "")
                        + ", which dempano cannot read (only stored and Deflate); unzip it, or zip it again with Deflate", e);
            }
            throw new DemException(file + " is not a zip archive, or a corrupt one (" + e.getMessage() + ")", e);
        } catch (IOException e) {
            throw new DemException(file + ": cannot read (" + e + ")", e);
        }
        return decode(id, file.toString(), bytes, fill);
    }

    /**
     * Decodes the raw bytes of a {@code .hgt} file for a known tile, and runs the cheap plausibility
     * checks (rows of zeros right below land, needles) whose findings become the tile's
     * {@link HgtTile#warnings()}.
     */
    public static HgtTile decode(TileId id, String source, byte[] bytes) {
        return decode(id, source, bytes, VoidFill.DEFAULT);
    }

    /** {@link #decode(TileId, String, byte[])} with the given void fill. */
    public static HgtTile decode(TileId id, String source, byte[] bytes, VoidFill fill) {
        int n = samplesForLength(source, bytes.length);
        float[] heights = new float[n * n];
        ByteBuffer buf = ByteBuffer.wrap(bytes).order(ByteOrder.BIG_ENDIAN);
        for (int i = 0; i < heights.length; i++) {
            short v = buf.getShort();
            if (v == VOID) {
                heights[i] = Float.NaN;
            } else if (v < MIN_PLAUSIBLE_METRES || v > MAX_PLAUSIBLE_METRES) {
                throw new DemException(source + ": implausible height " + v + " m at row " + (i / n) + ", column "
                        + (i % n) + " (corrupt file, or not big-endian int16?)");
            } else {
                heights[i] = v;
            }
        }
        java.util.List<String> warnings = new java.util.ArrayList<>(2);
        String zeros = Plausibility.zeroRowsBelowLand(heights, n, source); // before filling: voids are NaN
        if (zeros != null) {
            warnings.add(zeros);
        }
        java.util.BitSet mask = VoidFiller.voidMask(heights);
        VoidReport voids = VoidFiller.fill(heights, n, fill);
        String needles = Plausibility.needles(heights, n, id, source);
        if (needles != null) {
            warnings.add(needles);
        }
        return new HgtTile(id, source, n, heights, voids, mask, warnings).withVerticalDatum(DemContribution.EGM96);
    }

    private static int samplesForLength(String source, long length) {
        if (length == 2L * HgtTile.SRTM3_SAMPLES * HgtTile.SRTM3_SAMPLES) {
            return HgtTile.SRTM3_SAMPLES;
        }
        if (length == 2L * HgtTile.SRTM1_SAMPLES * HgtTile.SRTM1_SAMPLES) {
            return HgtTile.SRTM1_SAMPLES;
        }
        throw new DemException(source + ": " + length + " bytes is not an SRTM tile (expected "
                + 2L * HgtTile.SRTM3_SAMPLES * HgtTile.SRTM3_SAMPLES + " for SRTM3 or "
                + 2L * HgtTile.SRTM1_SAMPLES * HgtTile.SRTM1_SAMPLES + " for SRTM1; truncated or not a .hgt?)");
    }

    /**
     * A gzipped {@code .hgt} (as AWS Terrain Tiles serve them). Read at most an SRTM1 tile's bytes and one more, so a
     * gzip bomb cannot exhaust memory; read to its end, the stream checks its CRC-32 and length.
     */
    private static byte[] gunzip(Path file) throws IOException {
        long max = 2L * HgtTile.SRTM1_SAMPLES * HgtTile.SRTM1_SAMPLES;
        byte[] bytes;
        try (InputStream in = new java.util.zip.GZIPInputStream(Files.newInputStream(file), 1 << 16)) {
            bytes = in.readNBytes((int) max + 1);
            if (bytes.length > max) {
                throw new DemException(file + ": inflates to more than an SRTM1 tile's " + max
                        + " bytes (not a gzipped .hgt, or a corrupt file)");
            }
        } catch (ZipException | java.io.EOFException e) {
            throw new DemException(file + " is not a gzip file, or a corrupt or truncated one (" + e.getMessage()
                    + "); fetch the tile again", e);
        }
        return bytes;
    }

    /** Zip compression methods Java's zip reader does not read, by name (APPNOTE 4.4.5). */
    private static final java.util.Map<Integer, String> ZIP_METHODS = java.util.Map.of(9, "Deflate64", 12, "bzip2", 14, "LZMA",
            93, "Zstandard", 95, "xz", 98, "PPMd", 99, "AES-encrypted");

    /**
     * The one {@code .hgt} entry of a zip, read through the central directory. An entry named like a
     * tile must be the zip's own tile; other entry names (e.g. {@code data.hgt}) are accepted.
     */
    private static byte[] unzip(Path file, TileId id) throws IOException {
        try (ZipFile zip = new ZipFile(file.toFile())) {
            ZipEntry found = null;
            for (java.util.Enumeration<? extends ZipEntry> en = zip.entries(); en.hasMoreElements(); ) {
                ZipEntry e = en.nextElement();
                String name = e.getName();
                if (e.isDirectory() || !name.toLowerCase(java.util.Locale.ROOT).endsWith(".hgt")) {
                    continue;
                }
                if (found != null) {
                    throw new DemException(file + ": zip holds more than one .hgt (" + found.getName() + ", " + name + ")");
                }
                found = e;
            }
            if (found == null) {
                throw new DemException(file + ": zip holds no .hgt file");
            }
            String base = found.getName().substring(found.getName().lastIndexOf('/') + 1);
            if (TileId.isTileFileName(base) && !TileId.parseFileName(base).equals(id)) {
                throw new DemException(file + ": its name says tile " + id + " but the zip holds " + found.getName()
                        + " (tile " + TileId.parseFileName(base) + "); rename the file or fetch the right tile");
            }
            // Its size first (recorded in the central directory): an entry of another size is no tile, whatever it holds.
            if (found.getSize() >= 0) {
                samplesForLength(file + ": its entry " + found.getName(), found.getSize());
            }
            byte[] bytes;
            try (InputStream in = zip.getInputStream(found)) {
                // Cap the read so a lying archive cannot exhaust memory.
                bytes = in.readNBytes(2 * HgtTile.SRTM1_SAMPLES * HgtTile.SRTM1_SAMPLES + 1);
            }
            if (bytes.length > 2 * HgtTile.SRTM1_SAMPLES * HgtTile.SRTM1_SAMPLES) {
                throw new DemException(file + ": its entry " + found.getName() + " holds more than an SRTM1 tile's "
                        + 2L * HgtTile.SRTM1_SAMPLES * HgtTile.SRTM1_SAMPLES + " bytes (not a .hgt, or a corrupt zip)");
            }
            // ZipFile checks no checksum: a flipped bit in a stored (or deflated) entry would be a wrong height.
            java.util.zip.CRC32 crc = new java.util.zip.CRC32();
            crc.update(bytes);
            if (found.getCrc() == -1 || crc.getValue() != found.getCrc()) {
                throw new DemException(file + ": corrupt zip: the checksum of " + found.getName() + " does not match"
                        + (found.getCrc() == -1 ? " (the archive records none)" : String.format(
                        " (CRC-32 %08x recorded, %08x read)", found.getCrc(), crc.getValue())) + "; fetch the tile again");
            }
            return bytes;
        }
    }
}

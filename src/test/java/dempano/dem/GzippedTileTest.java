package dempano.dem;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.SharedData;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.zip.GZIPOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Gzipped tiles ({@code N46E008.hgt.gz}, as AWS Terrain Tiles serve them, also in their folder per latitude) read as the
 * {@code .hgt} they hold; a corrupt, truncated or oversized gzip is an error naming the file; a missing tile's file
 * there under a name that is not read is named in the error.
 */
class GzippedTileTest {
    private static void gzip(byte[] bytes, Path to) throws IOException {
        Files.createDirectories(to.getParent());
        try (OutputStream out = new GZIPOutputStream(Files.newOutputStream(to))) {
            out.write(bytes);
        }
    }

    @Test
    void aGzippedTileInItsLatitudeFolderReadsAsTheHgt(@TempDir Path dir) throws IOException {
        Path hgt = SharedData.demFile("N46E008.hgt");
        gzip(Files.readAllBytes(hgt), dir.resolve("N46").resolve("N46E008.hgt.gz")); // the "skadi" layout
        HgtTile plain = HgtReader.read(hgt);
        HgtTile gz = new DemDirectory(dir).tile(new TileId(46, 8)).orElseThrow();
        assertEquals(plain.samplesPerSide(), gz.samplesPerSide());
        for (int r = 0; r < plain.samplesPerSide(); r++) {
            for (int c = 0; c < plain.samplesPerSide(); c++) {
                assertEquals(plain.heightMetres(r, c), gz.heightMetres(r, c), "sample " + r + ", " + c);
            }
        }
        assertEquals(plain.voids().voidCells(), gz.voids().voidCells());
    }

    @Test
    void aCorruptTruncatedOrOversizedGzipIsAnErrorNamingTheFile(@TempDir Path dir) throws IOException {
        byte[] tile = new byte[2 * 1201 * 1201];
        Path good = dir.resolve("good").resolve("N46E008.hgt.gz");
        gzip(tile, good);
        byte[] bytes = Files.readAllBytes(good);

        Path truncated = Files.createDirectories(dir.resolve("truncated")).resolve("N46E008.hgt.gz");
        Files.write(truncated, java.util.Arrays.copyOf(bytes, bytes.length / 2));
        Path flipped = Files.createDirectories(dir.resolve("flipped")).resolve("N46E008.hgt.gz");
        byte[] f = bytes.clone();
        f[f.length - 6] ^= 0x5a; // in the trailer's CRC-32: the content no longer matches it
        Files.write(flipped, f);
        Path notGzip = Files.createDirectories(dir.resolve("plain")).resolve("N46E008.hgt.gz");
        Files.write(notGzip, tile);
        Path bomb = dir.resolve("bomb").resolve("N46E008.hgt.gz");
        gzip(new byte[2 * 3601 * 3601 + 2], bomb);
        for (Path p : new Path[] {truncated, flipped, notGzip}) {
            DemException e = assertThrows(DemException.class, () -> HgtReader.read(p));
            assertTrue(e.getMessage().startsWith(p + " is not a gzip file, or a corrupt or truncated one"), e.getMessage());
        }
        DemException e = assertThrows(DemException.class, () -> HgtReader.read(bomb));
        assertTrue(e.getMessage().contains("inflates to more than an SRTM1 tile's 25934402 bytes"), e.getMessage());
        assertEquals(0f, HgtReader.read(good).heightMetres(600, 600));
    }

    @Test
    void aMissingTilesFileUnderANameNotReadIsNamed(@TempDir Path dir) throws IOException {
        Files.write(dir.resolve("N46E008.hgt.bak"), new byte[0]);
        Files.write(dir.resolve("N46E008.tif.aux.xml"), new byte[0]);
        Files.write(dir.resolve("N45E008.hgt.bak"), new byte[0]); // another tile's: not named
        DemDirectory dem = new DemDirectory(dir);
        DemException e = assertThrows(DemException.class, () -> Mosaic.around(dem, 46.5, 8.5, 5000, MissingTilePolicy.ERROR));
        assertTrue(e.getMessage().contains("[" + dir.resolve("N46E008.hgt.bak") + ", " + dir.resolve("N46E008.tif.aux.xml")
                + "] are named for a missing tile but not read as one"), e.getMessage());
        assertTrue(!e.getMessage().contains("N45E008"), e.getMessage());
        Mosaic sea = Mosaic.around(dem, 46.5, 8.5, 5000, MissingTilePolicy.SEA_LEVEL);
        assertTrue(sea.warnings().stream().anyMatch(w -> w.startsWith("[" + dir.resolve("N46E008.hgt.bak"))), sea.warnings().toString());
        DemException auto = assertThrows(DemException.class, () -> MissingTilePolicy.AUTO.checkData(
                Mosaic.around(dem, 46.5, 8.5, 5000, MissingTilePolicy.AUTO), 46.5, 8.5, Double.NaN));
        assertTrue(auto.getMessage().contains("N46E008.hgt.bak"), auto.getMessage());
    }
}

package dempano.dem;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class HgtReaderTest {
    @TempDir
    Path dir;

    // A pattern that tells rows from columns and catches byte-order mistakes: h = 2500 + 3r - 2c.
    private static int pattern(int r, int c) {
        return 2500 + 3 * r - 2 * c;
    }

    @Test
    void readsSrtm3RowMajorNorthFirstBigEndian() throws IOException {
        Path f = HgtTestFiles.write(dir, "N45E007.hgt", HgtTestFiles.bytes(1201, HgtReaderTest::pattern));
        HgtTile t = HgtReader.read(f);
        assertEquals(new TileId(45, 7), t.id());
        assertEquals(1201, t.samplesPerSide());
        for (int[] rc : new int[][] {{0, 0}, {0, 1200}, {1200, 0}, {600, 17}, {1200, 1200}}) {
            assertEquals(pattern(rc[0], rc[1]), t.heightMetres(rc[0], rc[1]), 0, Arrays.toString(rc));
        }
        // Row 0 is the northern edge: the NW corner is (46N, 7E).
        assertEquals(pattern(0, 0), t.heightAt(46, 7), 1e-9);
        assertEquals(pattern(1200, 1200), t.heightAt(45, 8), 1e-9);
        assertEquals(VoidReport.NONE, t.voids());
    }

    @Test
    void readsSrtm1BySize() throws IOException {
        Path f = HgtTestFiles.write(dir, "S01W001.hgt", HgtTestFiles.bytes(3601, (r, c) -> (r + c) % 1000));
        HgtTile t = HgtReader.read(f);
        assertEquals(3601, t.samplesPerSide());
        assertEquals(3600, t.intervalsPerDegree());
        assertEquals((3600 + 5) % 1000, t.heightMetres(3600, 5), 0);
    }

    @Test
    void readsZipWithSuffixedName() throws IOException {
        Path inner = HgtTestFiles.write(dir, "N19W155.hgt", HgtTestFiles.bytes(1201, HgtReaderTest::pattern));
        Path zip = HgtTestFiles.zip(dir, "N19W155v2.3a.hgt.zip", "N19W155.hgt", inner.toString());
        HgtTile t = HgtReader.read(zip);
        assertEquals(new TileId(19, -155), t.id());
        assertEquals(pattern(7, 9), t.heightMetres(7, 9), 0);
    }

    @Test
    void truncatedFileIsAnErrorNamingFileAndSize() throws IOException {
        byte[] full = HgtTestFiles.bytes(1201, HgtReaderTest::pattern);
        Path f = HgtTestFiles.write(dir, "N45E007.hgt", Arrays.copyOf(full, full.length - 2));
        DemException e = assertThrows(DemException.class, () -> HgtReader.read(f));
        assertTrue(e.getMessage().contains("N45E007.hgt") && e.getMessage().contains("2884800 bytes"), e.getMessage());
    }

    @Test
    void misSizedFileIsAnError() throws IOException {
        Path f = HgtTestFiles.write(dir, "N45E007.hgt", new byte[2 * 1200 * 1200]);
        DemException e = assertThrows(DemException.class, () -> HgtReader.read(f));
        assertTrue(e.getMessage().contains("not an SRTM tile"), e.getMessage());
    }

    @Test
    void misnamedFileIsAnError() throws IOException {
        Path f = HgtTestFiles.write(dir, "alps.hgt", HgtTestFiles.bytes(1201, HgtReaderTest::pattern));
        DemException e = assertThrows(DemException.class, () -> HgtReader.read(f));
        assertTrue(e.getMessage().contains("alps.hgt"), e.getMessage());
    }

    @Test
    void littleEndianFileIsAnErrorNotAWrongPicture() throws IOException {
        // 300 m stored little-endian reads as 11265 m big-endian: implausible.
        Path f = HgtTestFiles.write(dir, "N45E007.hgt", HgtTestFiles.bytes(1201, (r, c) -> Short.reverseBytes((short) 300)));
        DemException e = assertThrows(DemException.class, () -> HgtReader.read(f));
        assertTrue(e.getMessage().contains("implausible height"), e.getMessage());
    }

    @Test
    void zipProblemsAreErrors() throws IOException {
        Path inner = HgtTestFiles.write(dir, "a.hgt", HgtTestFiles.bytes(1201, HgtReaderTest::pattern));
        Path readme = HgtTestFiles.write(dir, "readme.txt", new byte[] {'x'});
        Path two = HgtTestFiles.zip(dir, "N01E001.hgt.zip", "a.hgt", inner.toString(), "b.hgt", inner.toString());
        assertTrue(assertThrows(DemException.class, () -> HgtReader.read(two)).getMessage().contains("more than one"));
        Path none = HgtTestFiles.zip(dir, "N01E002.hgt.zip", "readme.txt", readme.toString());
        assertTrue(assertThrows(DemException.class, () -> HgtReader.read(none)).getMessage().contains("no .hgt"));
        Path garbage = HgtTestFiles.write(dir, "N01E003.hgt.zip", new byte[] {1, 2, 3, 4, 5});
        DemException e = assertThrows(DemException.class, () -> HgtReader.read(garbage));
        assertTrue(e.getMessage().contains("N01E003.hgt.zip"), e.getMessage());
    }

    @Test
    void missingFileIsAnError() {
        DemException e = assertThrows(DemException.class, () -> HgtReader.read(dir.resolve("N01E001.hgt")));
        assertTrue(e.getMessage().contains("no such file"), e.getMessage());
    }

    @Test
    void voidsAreFilledNeverPits() throws IOException {
        // A 20×20 void block in a plane: filled heights stay within the plane's range there.
        Path f = HgtTestFiles.write(dir, "N45E007.hgt", HgtTestFiles.bytes(1201,
                (r, c) -> (r >= 500 && r < 520 && c >= 700 && c < 720) ? HgtReader.VOID : pattern(r, c)));
        HgtTile t = HgtReader.read(f);
        assertEquals(400, t.voids().voidCells());
        assertEquals(1, t.voids().regions());
        assertEquals(20, t.voids().largestRegionSpanSamples());
        assertTrue(t.voids().hasLargeRegion());
        assertFalse(t.entirelyVoid());
        double lo = pattern(499, 720), hi = pattern(520, 699);
        for (int r = 500; r < 520; r++) {
            for (int c = 700; c < 720; c++) {
                float h = t.heightMetres(r, c);
                assertTrue(h >= lo && h <= hi, "filled " + h + " at " + r + "," + c);
            }
        }
    }

    @Test
    void entirelyVoidTileIsReported() throws IOException {
        Path f = HgtTestFiles.write(dir, "N45E007.hgt", HgtTestFiles.bytes(1201, (r, c) -> HgtReader.VOID));
        HgtTile t = HgtReader.read(f);
        assertTrue(t.entirelyVoid());
        assertEquals(0, t.heightMetres(600, 600), 0);
    }

    @Test
    void emptyDirectoryAndMissingDirectory() {
        assertThrows(DemException.class, () -> new DemDirectory(dir.resolve("nope")));
        assertTrue(new DemDirectory(dir).tile(new TileId(1, 1)).isEmpty());
    }

    @Test
    void directoryIndexesSuffixedAndLowercaseNames() throws IOException {
        Path inner = HgtTestFiles.write(dir, "tmp.bin", HgtTestFiles.bytes(1201, HgtReaderTest::pattern));
        HgtTestFiles.zip(dir, "S16E166v2.3a.hgt.zip", "S16E166.hgt", inner.toString());
        Files.copy(inner, dir.resolve("n45e007.hgt"));
        DemDirectory d = new DemDirectory(dir);
        assertEquals(2, d.files().size());
        assertEquals(pattern(3, 4), d.tile(new TileId(-16, 166)).orElseThrow().heightMetres(3, 4), 0);
        HgtTile a = d.tile(new TileId(45, 7)).orElseThrow();
        HgtTile b = d.tile(new TileId(45, 7)).orElseThrow();
        assertTrue(a == b, "second request served from the cache");
    }
}

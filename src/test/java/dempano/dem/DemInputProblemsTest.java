package dempano.dem;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.SharedData;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Bad DEM folders and tiles (issue 15, "Tiles and places"): each is an error naming the entry and the
 * problem, or renders with a warning saying what is odd; never silently a wrong picture.
 */
class DemInputProblemsTest {
    @TempDir
    Path dir;

    @Test
    void aTileGivenForItsFolderOrAMissingFolderIsSaidSo() throws IOException {
        Path tile = HgtTestFiles.write(dir, "N43E007.hgt", srtm3(new TileId(43, 7), 0));
        DemException e = assertThrows(DemException.class, () -> new DemDirectory(tile));
        assertEquals("DEM directory " + tile + " is a file, not a folder: give the folder that holds the tiles (" + dir.toAbsolutePath() + ")",
                e.getMessage());
        e = assertThrows(DemException.class, () -> new DemDirectory(dir.resolve("none")));
        assertEquals("DEM directory " + dir.resolve("none") + " does not exist", e.getMessage());
    }

    /** Smooth terrain continuous across tiles, so neighbouring tiles' shared edges agree. */
    static int terrain(double lat, double lon) {
        return (int) Math.round(600 + 250 * Math.sin(lat * 9) + 200 * Math.cos(lon * 7));
    }

    /** An SRTM3 tile of {@link #terrain} (plus an offset), as .hgt bytes. */
    static byte[] srtm3(TileId id, int offset) {
        return HgtTestFiles.bytes(1201, (r, c) -> terrain(id.latSouthDeg() + 1 - r / 1200.0, id.lonWestDeg() + c / 1200.0) + offset);
    }

    static Path tile(Path dir, String name) throws IOException {
        return HgtTestFiles.write(dir, name, srtm3(TileId.parseFileName(name), 0));
    }

    interface Setup {
        void in(Path dir) throws IOException;
    }

    /**
     * Table: a folder, a viewpoint and policy (range 10 km; 43.5, 7.5 needs N43E007 alone; 43.5, 7.05
     * also N43E006), and what must come out: the exception's message parts, or the warnings' parts.
     * "{dir}" stands for the folder.
     */
    static Stream<Arguments> cases() {
        List<Arguments> t = new ArrayList<>();
        t.add(Arguments.of("directory named like the tile", (Setup) d -> Files.createDirectory(d.resolve("N43E007.hgt")),
                43.5, 7.5, MissingTilePolicy.AUTO, Double.NaN, true, List.of("{dir}/N43E007.hgt", "is a directory")));
        t.add(Arguments.of("dangling symbolic link", (Setup) d -> Files.createSymbolicLink(d.resolve("N43E007.hgt"),
                d.resolve("gone.hgt")), 43.5, 7.5, MissingTilePolicy.SEA_LEVEL, Double.NaN, true,
                List.of("{dir}/N43E007.hgt", "dangling symbolic link", "gone.hgt")));
        t.add(Arguments.of("symbolic link loop", (Setup) d -> {
            Files.createSymbolicLink(d.resolve("N43E007.hgt"), d.resolve("loop.hgt.part"));
            Files.createSymbolicLink(d.resolve("loop.hgt.part"), d.resolve("N43E007.hgt"));
        }, 43.5, 7.5, MissingTilePolicy.SEA_LEVEL, Double.NaN, true, List.of("{dir}/N43E007.hgt", "symbolic link loop")));
        t.add(Arguments.of("symbolic link to a directory", (Setup) d -> Files.createSymbolicLink(d.resolve("N43E007.hgt"),
                Files.createDirectory(d.resolve("sub"))), 43.5, 7.5, MissingTilePolicy.AUTO, Double.NaN, true,
                List.of("{dir}/N43E007.hgt", "symbolic link to a directory")));
        t.add(Arguments.of("three files for one tile", (Setup) d -> {
            tile(d, "N43E007.hgt");
            tile(d, "N43E007-broken.hgt");
            tile(d, "n43e007.hgt");
        }, 43.5, 7.5, MissingTilePolicy.AUTO, Double.NaN, true,
                List.of("N43E007 is ambiguous", "{dir} holds 3 files", "N43E007-broken.hgt", "N43E007.hgt,", "n43e007.hgt", "keep one")));
        t.add(Arguments.of(".hgt and .hgt.zip of one tile", (Setup) d -> {
            Path p = tile(d, "N43E007.hgt");
            HgtTestFiles.zip(d, "N43E007.hgt.zip", "N43E007.hgt", p.toString());
        }, 43.5, 7.5, MissingTilePolicy.AUTO, Double.NaN, true, List.of("N43E007 is ambiguous", "N43E007.hgt.zip", "keep one")));
        t.add(Arguments.of("a good file and a directory for one tile", (Setup) d -> {
            tile(d, "N43E007.hgt");
            Files.createDirectory(d.resolve("N43E007v2.hgt"));
        }, 43.5, 7.5, MissingTilePolicy.AUTO, Double.NaN, true, List.of("N43E007 is ambiguous", "N43E007v2.hgt (a directory")));
        t.add(Arguments.of("problems of tiles out of range do not matter", (Setup) d -> {
            tile(d, "N43E007.hgt");
            Files.createDirectory(d.resolve("N10E010.hgt"));
            Files.createSymbolicLink(d.resolve("N11E010.hgt"), d.resolve("nowhere"));
            tile(d, "N43E009.hgt");
            tile(d, "N43E009-copy.hgt");
            Files.write(d.resolve("N43E010.hgt.zip"), new byte[] {1, 2, 3});
        }, 43.5, 7.5, MissingTilePolicy.ERROR, Double.NaN, false, List.of()));
        t.add(Arguments.of("junk named like tiles is ignored with one warning", (Setup) d -> {
            tile(d, "N43E007.hgt");
            Files.write(d.resolve("N99E999.hgt"), new byte[] {1, 2});
            Files.write(d.resolve("foo.hgt"), new byte[] {1, 2});
            Files.write(d.resolve("SHA256SUMS"), new byte[] {1, 2});
            Files.write(d.resolve("README"), new byte[] {1, 2});
        }, 43.5, 7.5, MissingTilePolicy.ERROR, Double.NaN, false,
                List.of("ignored 2 files in {dir}", "[N99E999.hgt, foo.hgt]", "no valid tile name")));
        t.add(Arguments.of("zip holding another tile", (Setup) d -> {
            Path p = HgtTestFiles.write(d, "N48E010.hgt", srtm3(new TileId(48, 10), 0));
            HgtTestFiles.zip(d, "N43E007.hgt.zip", "N48E010.hgt", p.toString());
            Files.delete(p);
        }, 43.5, 7.5, MissingTilePolicy.AUTO, Double.NaN, true,
                List.of("{dir}/N43E007.hgt.zip", "says tile N43E007", "holds N48E010.hgt")));
        t.add(Arguments.of("zip with a neutral entry name is read", (Setup) d -> {
            Path p = HgtTestFiles.write(d, "data.bin", srtm3(new TileId(43, 7), 0));
            HgtTestFiles.zip(d, "N43E007.hgt.zip", "srtm/data.hgt", p.toString());
        }, 43.5, 7.5, MissingTilePolicy.ERROR, Double.NaN, false, List.of()));
        t.add(Arguments.of("random bytes named .hgt.zip", (Setup) d -> Files.write(d.resolve("N43E007.hgt.zip"),
                new java.util.Random(1).ints(5000, 0, 256).collect(java.io.ByteArrayOutputStream::new,
                        (o, b) -> o.write(b), (a, b) -> { }).toByteArray()),
                43.5, 7.5, MissingTilePolicy.AUTO, Double.NaN, true, List.of("{dir}/N43E007.hgt.zip", "is not a zip archive")));
        t.add(Arguments.of("stored zip with one bit flipped in its tile", (Setup) d -> {
            byte[] tile = srtm3(new TileId(43, 7), 0);
            byte[] zip = storedZip("N43E007.hgt", tile); // the tile's bytes as they are, so one can be flipped
            int sample = 2 * (600 * 1201 + 600) + 1; // the low byte of the sample under the viewpoint: still plausible
            zip[indexOf(zip, tile) + sample] ^= 4;
            Files.write(d.resolve("N43E007.hgt.zip"), zip);
        }, 43.5, 7.5, MissingTilePolicy.AUTO, Double.NaN, true,
                List.of("{dir}/N43E007.hgt.zip", "corrupt zip", "checksum of N43E007.hgt does not match")));
        t.add(Arguments.of("zip entry larger than any tile (its recorded size)", (Setup) d -> {
            Path p = Files.write(d.resolve("big.bin"), new byte[2 * 3601 * 3601 + 2]);
            HgtTestFiles.zip(d, "N43E007.hgt.zip", "N43E007.hgt", p.toString());
        }, 43.5, 7.5, MissingTilePolicy.AUTO, Double.NaN, true,
                List.of("{dir}/N43E007.hgt.zip: its entry N43E007.hgt: 25934404 bytes is not an SRTM tile")));
        t.add(Arguments.of("zip compressed with bzip2", (Setup) d -> {
            byte[] zip = storedZip("N43E007.hgt", srtm3(new TileId(43, 7), 0));
            // The method (2 bytes, little-endian) in the local header (offset 8) and the central directory's (10).
            zip[8] = 12;
            int central = zip.length - 4;
            while (!(zip[central] == 'P' && zip[central + 1] == 'K' && zip[central + 2] == 1 && zip[central + 3] == 2)) {
                central--;
            }
            zip[central + 10] = 12;
            Files.write(d.resolve("N43E007.hgt.zip"), zip);
        }, 43.5, 7.5, MissingTilePolicy.AUTO, Double.NaN, true,
                List.of("{dir}/N43E007.hgt.zip is compressed with zip method 12 (bzip2), which dempano cannot read")));
        t.add(Arguments.of("a tile without one valid sample", (Setup) d -> {
            byte[] voids = new byte[2 * 1201 * 1201];
            for (int i = 0; i < voids.length; i += 2) {
                voids[i] = (byte) 0x80; // -32768, big-endian
            }
            Files.write(d.resolve("N43E007.hgt"), voids);
        }, 43.5, 7.5, MissingTilePolicy.AUTO, Double.NaN, true,
                List.of("none of the tiles needed within range [N43E007] has data in", "{dir}/N43E007.hgt) has no valid sample at all")));
        t.add(Arguments.of("zip without .hgt", (Setup) d -> HgtTestFiles.zip(d, "N43E007.hgt.zip", "readme.txt",
                Files.write(d.resolve("readme.txt"), new byte[] {'x'}).toString()),
                43.5, 7.5, MissingTilePolicy.AUTO, Double.NaN, true, List.of("{dir}/N43E007.hgt.zip", "zip holds no .hgt file")));
        // Missing tiles.
        t.add(Arguments.of("auto: no tile at all", (Setup) d -> tile(d, "N10E010.hgt"), 43.5, 7.05, MissingTilePolicy.AUTO,
                Double.NaN, true, List.of("none of the tiles needed within range [N43E006, N43E007]", "is in {dir}", "--missing-tiles sea")));
        t.add(Arguments.of("auto: no tile at all, even with an altitude", (Setup) d -> { }, 43.5, 7.5, MissingTilePolicy.AUTO,
                1000.0, true, List.of("[N43E007]", "{dir}")));
        t.add(Arguments.of("auto: the viewpoint's tile missing", (Setup) d -> tile(d, "N43E006.hgt"), 43.5, 7.05,
                MissingTilePolicy.AUTO, Double.NaN, true, List.of("tile N43E007 under the viewpoint", "is not in {dir}",
                        "--altitude-m", "--missing-tiles sea")));
        t.add(Arguments.of("auto: the viewpoint's tile missing, altitude given", (Setup) d -> tile(d, "N43E006.hgt"), 43.5,
                7.05, MissingTilePolicy.AUTO, 100.0, false, List.of("no data for [N43E007] in {dir}", "sea level")));
        t.add(Arguments.of("auto: a neighbour missing (a coast)", (Setup) d -> tile(d, "N43E007.hgt"), 43.5, 7.05,
                MissingTilePolicy.AUTO, Double.NaN, false, List.of("no data for [N43E006] in {dir}", "sea level")));
        t.add(Arguments.of("auto: viewpoint on the edge of a present tile", (Setup) d -> tile(d, "N43E006.hgt"), 43.5, 7.0,
                MissingTilePolicy.AUTO, Double.NaN, false, List.of("no data for [N43E007]")));
        t.add(Arguments.of("sea: no tile at all is asked-for sea", (Setup) d -> { }, 43.5, 7.05, MissingTilePolicy.SEA_LEVEL,
                Double.NaN, false, List.of("no data for [N43E006, N43E007] in {dir}", "sea level")));
        t.add(Arguments.of("error: every missing tile listed", (Setup) d -> {
            tile(d, "N43E006.hgt");
            tile(d, "N44E006.hgt");
        }, 43.95, 7.05,
                MissingTilePolicy.ERROR, Double.NaN, true, List.of("2 tiles [N44E007, N43E007] are needed", "{dir}")));
        return t.stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void badFoldersAreErrorsOrWarningsNamingTheEntry(String name, Setup setup, double lat, double lon,
                                                      MissingTilePolicy policy, double altitude, boolean error,
                                                      List<String> expected) throws IOException {
        setup.in(dir);
        DemDirectory dem = new DemDirectory(dir); // never fails on the folder's content
        List<String> expect = expected.stream().map(s -> s.replace("{dir}", dir.toString())).toList();
        if (error) {
            DemException e = assertThrows(DemException.class, () -> {
                Mosaic m = Mosaic.around(dem, lat, lon, 10_000, policy);
                policy.checkData(m, lat, lon, altitude);
            });
            for (String s : expect) {
                assertTrue(e.getMessage().contains(s), "'" + s + "' not in: " + e.getMessage());
            }
        } else {
            Mosaic m = Mosaic.around(dem, lat, lon, 10_000, policy);
            policy.checkData(m, lat, lon, altitude);
            List<String> warnings = new ArrayList<>(dem.warnings());
            warnings.addAll(m.warnings());
            String all = String.join("\n", warnings);
            for (String s : expect) {
                assertTrue(all.contains(s), "'" + s + "' not in warnings: " + all);
            }
            if (expect.isEmpty()) {
                assertEquals(List.of(), warnings);
            }
        }
    }

    @Test
    void unreadableFileIsAnErrorNamingIt() throws IOException {
        Assumptions.assumeFalse("root".equals(System.getProperty("user.name")), "root reads every file; test skipped");
        Path p = tile(dir, "N43E007.hgt");
        p.toFile().setReadable(false, false);
        Assumptions.assumeFalse(Files.isReadable(p), "cannot make a file unreadable here; test skipped");
        DemException e = assertThrows(DemException.class, () -> new DemDirectory(dir).tile(new TileId(43, 7)));
        assertTrue(e.getMessage().contains(p.toString()) && e.getMessage().contains("not readable"), e.getMessage());
    }

    /** A zip of one entry stored uncompressed (its bytes as they are), with its checksum. */
    static byte[] storedZip(String name, byte[] content) throws IOException {
        java.util.zip.CRC32 crc = new java.util.zip.CRC32();
        crc.update(content);
        java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
        try (java.util.zip.ZipOutputStream z = new java.util.zip.ZipOutputStream(bytes)) {
            java.util.zip.ZipEntry e = new java.util.zip.ZipEntry(name);
            e.setMethod(java.util.zip.ZipEntry.STORED);
            e.setSize(content.length);
            e.setCrc(crc.getValue());
            z.putNextEntry(e);
            z.write(content);
            z.closeEntry();
        }
        return bytes.toByteArray();
    }

    /** Where {@code part}'s first 64 bytes start in {@code whole}. */
    static int indexOf(byte[] whole, byte[] part) {
        outer:
        for (int i = 0; i + 64 <= whole.length; i++) {
            for (int k = 0; k < 64; k++) {
                if (whole[i + k] != part[k]) {
                    continue outer;
                }
            }
            return i;
        }
        throw new AssertionError("not found");
    }

    // ---- Plausibility warnings ----

    /** An SRTM3 tile's data in an SRTM1-sized file, zeros after it: rows from about 400 on are 0. */
    @Test
    void srtm3DataPaddedIntoAnSrtm1FileWarns() throws IOException {
        byte[] small = srtm3(new TileId(43, 7), 0);
        byte[] big = new byte[2 * 3601 * 3601];
        System.arraycopy(small, 0, big, 0, small.length);
        Path p = HgtTestFiles.write(dir, "N43E007.hgt", big);
        HgtTile t = HgtReader.read(p);
        assertEquals(1, t.warnings().size(), t.warnings().toString());
        String w = t.warnings().get(0);
        int firstZeroRow = small.length / 2 / 3601 + 1;
        assertTrue(w.startsWith(p.toString()) && w.contains("rows " + firstZeroRow + " to 3600") && w.contains("exactly 0 m")
                && w.contains("which is land"), w);
        Mosaic m = Mosaic.around(new DemDirectory(dir), 43.5, 7.5, 10_000, MissingTilePolicy.AUTO);
        assertTrue(m.warnings().contains(w), "the tile's warning is the mosaic's: " + m.warnings());
    }

    /** Sea below a coast, and land ending in a row of zeros only where it is low or sparse: no warning. */
    @ParameterizedTest(name = "{0}")
    @org.junit.jupiter.params.provider.ValueSource(strings = {"diagonal coast", "low flat shore", "sparse islands", "all sea", "land to the edge"})
    void coastsDoNotWarn(String kind) throws IOException {
        Path p = HgtTestFiles.write(dir, "N43E007.hgt", HgtTestFiles.bytes(1201, (r, c) -> switch (kind) {
            case "diagonal coast" -> r + c < 1300 ? 50 + (1300 - r - c) : 0;
            case "low flat shore" -> r < 800 ? (r < 799 ? 300 : 5) : 0;     // the last land row is low
            case "sparse islands" -> r < 800 ? (r < 799 || c % 3 == 0 ? 300 : 0) : 0; // a third of the row is land
            case "all sea" -> 0;
            default -> 200 + r % 7;
        }));
        assertEquals(List.of(), HgtReader.read(p).warnings());
    }

    /** A straight cut: land rows then zeros, one row of difference between warning and not. */
    @Test
    void zeroRowsBelowLandWarnNamingTheRows() throws IOException {
        Path p = HgtTestFiles.write(dir, "N43E007.hgt", HgtTestFiles.bytes(1201, (r, c) -> r < 700 ? 40 + c % 5 : 0));
        List<String> w = HgtReader.read(p).warnings();
        assertEquals(1, w.size(), w.toString());
        assertTrue(w.get(0).contains("rows 700 to 1200") && w.get(0).contains("below row 699") && w.get(0).contains("mean 42 m"),
                w.get(0));
    }

    // A block up to 5×5 has samples whose ring 3 samples away lies outside it: all 9 of a 3×3, the centre of a 5×5.
    @ParameterizedTest(name = "{0}×{0} block of {1} m")
    @org.junit.jupiter.params.provider.CsvSource({"1, 8999, 1, 0", "3, 8999, 9, 0", "5, 8999, 1, 2", "3, 2800, 9, 0"})
    void needlesWarn(int size, int height, int samples, int firstAt) throws IOException {
        TileId id = new TileId(43, 7);
        int r0 = 600, c0 = 300;
        Path p = HgtTestFiles.write(dir, "N43E007.hgt", HgtTestFiles.bytes(1201, (r, c) ->
                r >= r0 && r < r0 + size && c >= c0 && c < c0 + size ? height
                        : terrain(id.latSouthDeg() + 1 - r / 1200.0, id.lonWestDeg() + c / 1200.0)));
        List<String> w = HgtReader.read(p).warnings();
        assertEquals(1, w.size(), w.toString());
        assertTrue(w.get(0).startsWith(p.toString()) && w.get(0).contains(": " + samples + " sample")
                && w.get(0).contains("highest " + height + " m at row " + (r0 + firstAt) + ", column " + (c0 + firstAt)) && w.get(0).contains("needle"),
                w.get(0));
    }

    /** Steep real-looking relief (a 900 m wall, a 7×7 tower) is no needle. */
    @ParameterizedTest(name = "{0}")
    @org.junit.jupiter.params.provider.ValueSource(strings = {"wall", "tower 7x7", "cone"})
    void steepReliefIsNoNeedle(String kind) throws IOException {
        Path p = HgtTestFiles.write(dir, "N43E007.hgt", HgtTestFiles.bytes(1201, (r, c) -> switch (kind) {
            case "wall" -> c < 600 ? 100 : 3000;
            case "tower 7x7" -> Math.abs(r - 600) <= 3 && Math.abs(c - 600) <= 3 ? 5000 : 500;
            default -> (int) Math.max(200, 4000 - 330 * Math.hypot(r - 600, c - 600)); // 330 m per sample, 990 m at 3
        }));
        assertEquals(List.of(), HgtReader.read(p).warnings());
    }

    @ParameterizedTest(name = "offset {0} m")
    @org.junit.jupiter.params.provider.CsvSource({"0, false", "8, false", "40, true"})
    void disagreeingSharedEdgesWarn(int offset, boolean warns) throws IOException {
        tile(dir, "N43E006.hgt");
        HgtTestFiles.write(dir, "N43E007.hgt", srtm3(new TileId(43, 7), offset));
        tile(dir, "N44E007.hgt");
        Mosaic m = Mosaic.around(new DemDirectory(dir), 43.95, 7.02, 20_000, MissingTilePolicy.AUTO);
        List<String> edges = m.warnings().stream().filter(w -> w.contains("disagree")).toList();
        assertEquals(warns ? 2 : 0, edges.size(), m.warnings().toString());
        if (warns) {
            assertTrue(edges.get(0).contains("N44E007 (" + dir.resolve("N44E007.hgt") + ") and N43E007 ("
                    + dir.resolve("N43E007.hgt") + ")") && edges.get(0).contains("mean |difference| 40.0 m, max 40 m over 1201"),
                    edges.get(0));
            assertTrue(edges.get(1).contains("N43E006") && edges.get(1).contains("eastern edge"), edges.get(1));
        }
    }

    // ---- The real tiles: none warns, and the checks are cheap ----

    @ParameterizedTest
    @org.junit.jupiter.params.provider.ValueSource(strings = {"N00E010.hgt", "N19W155v2.3a.hgt.zip", "N22W160v2.3a.hgt.zip",
            "N43E006.hgt", "N43E007.hgt", "N44E033.hgt", "N44W072.hgt", "N46E008.hgt", "N48E009.hgt", "N48E010.hgt",
            "S16E166v2.3a.hgt.zip"})
    void realTilesDoNotWarn(String file) {
        HgtTile t = HgtReader.read(SharedData.demFile(file));
        assertEquals(List.of(), t.warnings());
    }

    @ParameterizedTest
    @org.junit.jupiter.params.provider.CsvSource({"43.5, 7.0", "48.5, 10.0"})
    void realNeighboursShareTheirEdges(double lat, double lon) {
        Mosaic m = Mosaic.around(new DemDirectory(SharedData.demDir()), lat, lon, 20_000, MissingTilePolicy.ERROR);
        assertEquals(2, m.tilesUsed().size());
        assertEquals(List.of(), m.warnings().stream().filter(w -> w.contains("disagree")).toList());
    }

    /** Cost of the checks on a worst case for the pre-check (rough terrain); printed for the record. */
    @ParameterizedTest
    @org.junit.jupiter.params.provider.ValueSource(ints = {1201, 3601})
    void checksAreCheap(int n) {
        float[] h = new float[n * n];
        java.util.Random rnd = new java.util.Random(3);
        for (int i = 0; i < h.length; i++) {
            h[i] = 1500 + rnd.nextInt(400); // rough: the pre-check passes nowhere, every sample is looked at
        }
        TileId id = new TileId(46, 8);
        long best = Long.MAX_VALUE, bestZero = Long.MAX_VALUE;
        for (int k = 0; k < 5; k++) {
            long t0 = System.nanoTime();
            assertEquals(null, Plausibility.needles(h, n, id, "rough"));
            long t1 = System.nanoTime();
            assertEquals(null, Plausibility.zeroRowsBelowLand(h, n, "rough"));
            long t2 = System.nanoTime();
            best = Math.min(best, t1 - t0);
            bestZero = Math.min(bestZero, t2 - t1);
        }
        System.out.printf(Locale.ROOT, "plausibility checks on %d²: needles %.1f ms, zero rows %.3f ms%n", n, best / 1e6,
                bestZero / 1e6);
        assertTrue(best < 2_000_000_000L, "needle check " + best / 1e6 + " ms");
    }
}

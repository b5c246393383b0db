package dempano.dem;

import static dempano.dem.GeoTiffTestFiles.DEFLATE;
import static dempano.dem.GeoTiffTestFiles.LZW;
import static dempano.dem.GeoTiffTestFiles.NONE;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.dem.GeoTiffTestFiles.SampleType;
import dempano.dem.GeoTiffTestFiles.Spec;
import java.io.IOException;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * GeoTIFFs written from the specification at test time (see {@link GeoTiffTestFiles}) with known
 * heights, read back sample by sample and at known coordinates.
 */
class GeoTiffReaderTest {
    @TempDir
    Path dir;

    /** 30″ pixels: tile N46E008 has 121 × 121 samples on its edges. */
    private static final double D = 1.0 / 120;

    /** Integer heights known per pixel, linear in row and column (so linear in lat/lon too). */
    private static int plane(int row, int col) {
        return 1000 + 3 * row - 2 * col;
    }

    /** The same plane as a function of coordinates, for a grid with pixel (0,0) centred on (47°N, 8°E). */
    private static double planeAt(double latDeg, double lonDeg) {
        return 1000 + 3 * (47 - latDeg) / D - 2 * (lonDeg - 8) / D;
    }

    /** 121 × 121 pixels centred on the edges of tile N46E008 (as SRTM and gdal_translate of .hgt lay them out). */
    private static Spec srtmLike(boolean pixelIsPoint) {
        return GeoTiffTestFiles.geographic(121, 121, 8, 47, D, D, pixelIsPoint);
    }

    @ParameterizedTest(name = "{0} compression {1} predictor {2}, tiles {3}, strips of {4}, {5}, {6}")
    @CsvSource({
            "INT16, 1, 1, 0, 7, LE, point",
            "INT16, 1, 1, 32, 0, BE, area",
            "INT16, 5, 1, 0, 121, LE, area",
            "INT16, 5, 2, 16, 0, LE, point",
            "INT16, 5, 2, 0, 5, BE, area",
            "INT16, 8, 1, 0, 16, BE, point",
            "INT16, 8, 2, 48, 0, LE, area",
            "INT16, 8, 2, 0, 1, BE, point",
            "INT32, 1, 1, 0, 8, BE, area",
            "INT32, 5, 2, 32, 0, LE, point",
            "INT32, 8, 2, 0, 3, LE, area",
            "FLOAT32, 1, 1, 16, 0, LE, area",
            "FLOAT32, 5, 1, 0, 9, BE, point",
            "FLOAT32, 5, 3, 32, 0, LE, area",
            "FLOAT32, 8, 3, 0, 11, LE, point",
            "FLOAT32, 8, 3, 64, 0, BE, area",
            "FLOAT32, 5, 3, 48, 0, BE, point",
            "INT32, 8, 2, 0, 4, BE, point",
            "FLOAT32, 8, 1, 0, 121, BE, area",
    })
    void readsEveryLayoutSampleBySampleAndAtItsCoordinates(SampleType type, int compression, int predictor, int tiles,
                                                           int rowsPerStrip, String order, String raster) throws IOException {
        boolean point = raster.equals("point");
        Spec s = srtmLike(point).withType(type).withCompression(compression, predictor)
                .withLayout(tiles, rowsPerStrip, order.equals("BE") ? ByteOrder.BIG_ENDIAN : ByteOrder.LITTLE_ENDIAN);
        // Floats get a fraction so float samples are not whole numbers in disguise.
        GeoTiffTestFiles.Values v = type == SampleType.FLOAT32 ? (r, c) -> plane(r, c) + 0.25 * ((r + c) % 4)
                : (r, c) -> plane(r, c);
        Path f = GeoTiffTestFiles.write(dir.resolve("N46E008.tif"), s, v);

        GeoTiffReader.Grid g = GeoTiffReader.readGrid(f);
        assertEquals(121, g.width());
        assertEquals(121, g.height());
        assertEquals(point, g.centres().pixelIsPoint());
        for (int r = 0; r < 121; r++) {
            for (int c = 0; c < 121; c++) {
                assertEquals((float) v.at(r, c), g.heightsMetres()[r * 121 + c], "pixel " + r + ", " + c);
            }
        }
        // Pixel centres on the tile's sample positions, whichever raster type: the tile is the grid.
        HgtTile t = GeoTiffReader.read(f);
        assertEquals(TileId.of(46, 8), t.id());
        assertEquals(121, t.samplesPerSide());
        for (int r = 0; r < 121; r++) {
            for (int c = 0; c < 121; c++) {
                assertEquals((float) v.at(r, c), t.heightMetres(r, c), "tile sample " + r + ", " + c);
            }
        }
        assertEquals(1000 + 3 * 60 - 2 * 24, t.heightAt(46.5, 8.2), 0.3, "height at 46.5°N 8.2°E");
    }

    /**
     * The same pixel centres declared as PixelIsArea (tiepoint on the pixel corner) and PixelIsPoint
     * (tiepoint on the centre) give the same tile; declaring the area file's tiepoint as a point
     * shifts every sample by half a pixel (1.5 m north-south, 1 m east-west on this plane), which
     * the comparison with the plane catches.
     */
    @Test
    void pixelIsAreaAndPixelIsPointLandOnTheSameCoordinates() throws IOException {
        Path area = GeoTiffTestFiles.write(dir.resolve("N46E008.tif"), srtmLike(false), GeoTiffReaderTest::plane);
        Path pointDir = Files.createDirectory(dir.resolve("p"));
        Path point = GeoTiffTestFiles.write(pointDir.resolve("N46E008.tif"), srtmLike(true), GeoTiffReaderTest::plane);
        HgtTile a = GeoTiffReader.read(area), p = GeoTiffReader.read(point);
        for (double lat = 46; lat <= 47; lat += 0.0371) {
            for (double lon = 8; lon <= 9; lon += 0.0413) {
                assertEquals(planeAt(lat, lon), a.heightAt(lat, lon), 1e-3, "area at " + lat + ", " + lon);
                assertEquals(planeAt(lat, lon), p.heightAt(lat, lon), 1e-3, "point at " + lat + ", " + lon);
            }
        }
        // Negative control: the corner tiepoint read as a centre is half a pixel north-west.
        Spec wrong = new Spec(121, 121, SampleType.INT16, NONE, 1, 0, 7, ByteOrder.LITTLE_ENDIAN,
                new double[] {8 - D / 2, 47 + D / 2}, new double[] {D, D}, null, 2, 2, 4326, 0, null, false, 0);
        Path shifted = GeoTiffTestFiles.write(Files.createDirectory(dir.resolve("w")).resolve("N46E008.tif"), wrong,
                GeoTiffReaderTest::plane);
        assertEquals(planeAt(46.5, 8.5) + 1.5 - 1, GeoTiffReader.read(shifted).heightAt(46.5, 8.5), 1e-3);
    }

    /**
     * Copernicus GLO tiles: 3600 × 3600 pixels (here 120 × 120) centred from the north-west corner, no
     * southern row or eastern column (they are the neighbours' first), and above 50° fewer columns.
     */
    @ParameterizedTest(name = "{0} columns per degree at {1}°N")
    @CsvSource({"120, 46", "80, 55", "60, 65", "40, 75", "24, 82"})
    void copernicusTilesIncludingWidthReducedOnesComeOutOnARegularGrid(int colsPerDegree, int latSouth) throws IOException {
        double dLon = 1.0 / colsPerDegree;
        Spec s = GeoTiffTestFiles.geographic(colsPerDegree, 120, 8, latSouth + 1, dLon, D, true)
                .withCompression(DEFLATE, 2).withLayout(16, 0, ByteOrder.LITTLE_ENDIAN);
        String name = String.format("Copernicus_DSM_COG_10_N%02d_00_E008_00_DEM.tif", latSouth);
        // Heights linear in lat/lon: 5 m per row (of 1/120°), 7 m per degree/colsPerDegree column.
        Path f = GeoTiffTestFiles.write(dir.resolve(name), s, (r, c) -> 2000 + 5 * r - 7 * c);
        HgtTile t = GeoTiffReader.read(f);
        assertEquals(TileId.of(latSouth, 8), t.id());
        assertEquals(121, t.samplesPerSide(), "the latitude resolution decides the grid");
        assertEquals(DemContribution.EGM2008, t.verticalDatum(), "Copernicus naming");
        for (int r = 0; r < 120; r++) {
            // Columns at 1/120°: pixel column c·colsPerDegree/120, up to the last pixel centre.
            for (int c = 0; c * colsPerDegree <= 120 * (colsPerDegree - 1); c++) {
                double expected = 2000 + 5 * r - 7.0 * c * colsPerDegree / 120;
                assertEquals(expected, t.heightMetres(r, c), 1e-3, "sample " + r + ", " + c);
            }
        }
        // The missing southern row and eastern column repeat the last pixels (the neighbour's would be used).
        assertEquals(2000 + 5 * 119, t.heightMetres(120, 0), 1e-3);
        assertEquals(2000 - 7 * (colsPerDegree - 1), t.heightMetres(0, 120), 1e-3);
        assertEquals(0, t.voids().voidCells());
    }

    /**
     * Copernicus tiles in one directory: the strip between a tile's last pixel centres and its
     * eastern / southern edge is interpolated towards the neighbours' first column / row, also across
     * a change of width (60°N: 60 columns per degree north of it, 80 south of it here). Heights linear
     * in lat/lon come out exact everywhere; a changed neighbour changes the cached tile.
     */
    @Test
    void copernicusTilesAreJoinedToTheirNeighboursAcrossWidthChanges() throws IOException {
        int[][] tiles = {{60, 8, 60}, {60, 9, 60}, {59, 8, 80}, {59, 9, 80}};
        for (int[] t : tiles) {
            writeCopernicus(t[0], t[1], t[2], 0);
        }
        DemDirectory dem = new DemDirectory(dir);
        HgtTile tile = dem.tile(TileId.of(60, 8)).orElseThrow();
        assertEquals(121, tile.samplesPerSide());
        for (int r = 0; r <= 120; r++) {
            for (int c = 0; c <= 120; c++) {
                assertEquals(linear(61 - r * D, 8 + c * D), tile.heightMetres(r, c), 2e-3, "sample " + r + ", " + c);
            }
        }
        assertEquals(java.util.List.of(), tile.warnings());
        // Without neighbours the last pixels repeat: the eastern edge sample is the last pixel's height.
        Path alone = Files.createDirectory(dir.resolve("alone"));
        Files.copy(dir.resolve(copernicusName(60, 8)), alone.resolve(copernicusName(60, 8)));
        HgtTile lonely = new DemDirectory(alone).tile(TileId.of(60, 8)).orElseThrow();
        assertEquals(linear(61, 8 + 59.0 / 60), lonely.heightMetres(0, 120), 2e-3);
        // The eastern neighbour rewritten 100 m higher: the cached tile's eastern strip follows.
        writeCopernicus(60, 9, 60, 100);
        Files.setLastModifiedTime(dir.resolve(copernicusName(60, 9)),
                java.nio.file.attribute.FileTime.fromMillis(System.currentTimeMillis() + 5000));
        HgtTile again = dem.tile(TileId.of(60, 8)).orElseThrow();
        assertEquals(linear(61, 9) + 100, again.heightMetres(0, 120), 2e-3);
        assertEquals(linear(61, 8.5), again.heightMetres(0, 60), 2e-3);
    }

    /** An unreadable neighbour does not fail the tile: its edge repeats the last pixels, with a warning naming both. */
    @Test
    void anUnreadableNeighbourLeavesTheEdgeUnjoinedWithAWarning() throws IOException {
        writeCopernicus(60, 8, 60, 0);
        Path broken = dir.resolve(copernicusName(60, 9));
        Files.write(broken, new byte[] {'I', 'I', 42, 0});
        HgtTile t = new DemDirectory(dir).tile(TileId.of(60, 8)).orElseThrow();
        assertEquals(linear(61, 8 + 59.0 / 60), t.heightMetres(0, 120), 2e-3);
        assertEquals(1, t.warnings().size(), t.warnings().toString());
        assertTrue(t.warnings().get(0).startsWith(dir.resolve(copernicusName(60, 8)) + ": edge towards N60E009 not joined ("
                + broken + " is not a readable TIFF file"), t.warnings().get(0));
    }

    private static double linear(double latDeg, double lonDeg) {
        return 1000 + 500 * (latDeg - 60) + 200 * (lonDeg - 8);
    }

    private static String copernicusName(int lat, int lon) {
        return String.format("Copernicus_DSM_COG_10_N%02d_00_E%03d_00_DEM.tif", lat, lon);
    }

    private void writeCopernicus(int lat, int lon, int colsPerDegree, double add) throws IOException {
        double dLon = 1.0 / colsPerDegree;
        Spec s = GeoTiffTestFiles.geographic(colsPerDegree, 120, lon, lat + 1, dLon, D, true).withType(SampleType.FLOAT32)
                .withCompression(DEFLATE, 3).withLayout(32, 0, ByteOrder.LITTLE_ENDIAN);
        GeoTiffTestFiles.write(dir.resolve(copernicusName(lat, lon)), s,
                (r, c) -> add + linear(lat + 1 - r * D, lon + c * dLon));
    }

    @Test
    void nodataAndNanAreVoids() throws IOException {
        Spec s = srtmLike(false).withNodata("-32768").withCompression(LZW, 2);
        Path f = GeoTiffTestFiles.write(dir.resolve("N46E008.tif"), s,
                (r, c) -> r >= 40 && r < 50 && c >= 60 && c < 75 ? -32768 : plane(r, c));
        HgtTile t = GeoTiffReader.read(f);
        assertEquals(150, t.voids().voidCells());
        assertTrue(t.isFilledVoid(45, 70));
        assertFalse(t.isFilledVoid(39, 70));
        // Filled from around: somewhere between the surrounding heights, never the nodata value.
        assertTrue(t.heightMetres(45, 70) > 950 && t.heightMetres(45, 70) < 1050, "filled " + t.heightMetres(45, 70));
        assertEquals(121L * 121 - 150, t.contributions().get(0).samples());

        Spec fl = srtmLike(true).withType(SampleType.FLOAT32).withCompression(DEFLATE, 3).withNodata("-9999");
        Path g = GeoTiffTestFiles.write(Files.createDirectory(dir.resolve("f")).resolve("N46E008.tif"), fl,
                (r, c) -> r == 3 && c == 4 ? Double.NaN : r == 100 ? -9999 : plane(r, c));
        HgtTile u = GeoTiffReader.read(g);
        assertEquals(1 + 121, u.voids().voidCells());
        assertTrue(u.isFilledVoid(3, 4));
        assertTrue(u.isFilledVoid(100, 0));
    }

    @Test
    void aProjectedCrsIsRefusedWithTheWayOut() throws IOException {
        Spec s = GeoTiffTestFiles.geographic(50, 50, 420_000, 5_200_000, 30, 30, false).withCrs(1, 32632, 0);
        Path f = GeoTiffTestFiles.write(dir.resolve("N46E008.tif"), s, (r, c) -> 500);
        DemException e = assertThrows(DemException.class, () -> GeoTiffReader.read(f));
        assertEquals(f + " is in a projected CRS (EPSG:32632); reproject it to geographic lat/lon, e.g. with "
                + "gdalwarp -t_srs EPSG:4326", e.getMessage());
    }

    @Test
    void aFileWithoutGeoKeysIsRefused() throws IOException {
        Spec s = srtmLike(false).withCrs(0, 0, 0);
        Path f = GeoTiffTestFiles.write(dir.resolve("N46E008.tif"), s, GeoTiffReaderTest::plane);
        DemException e = assertThrows(DemException.class, () -> GeoTiffReader.read(f));
        assertTrue(e.getMessage().startsWith(f + " has no GeoTIFF georeferencing keys"), e.getMessage());
    }

    @ParameterizedTest(name = "{0} bytes kept, {1} % of the file")
    @CsvSource({"0, -1", "5, -1", "8, -1", "100, -1", "-1, 50", "-1, 90", "-1, 99", "-1, -1"})
    void aTruncatedOrCorruptFileIsRefusedNamingIt(int keepBytes, int keepPercent) throws IOException {
        Spec s = srtmLike(false).withCompression(DEFLATE, 2);
        byte[] full = GeoTiffTestFiles.bytes(s, (r, c) -> plane(r, c));
        byte[] cut;
        if (keepBytes >= 0 || keepPercent >= 0) {
            cut = Arrays.copyOf(full, keepBytes >= 0 ? keepBytes : full.length * keepPercent / 100);
        } else {
            // The IFD (at the end) intact, image data scrambled.
            cut = full.clone();
            for (int i = 8; i < cut.length / 2; i++) {
                cut[i] = (byte) (i * 31);
            }
        }
        Path f = dir.resolve("N46E008.tif");
        Files.write(f, cut);
        DemException e = assertThrows(DemException.class, () -> GeoTiffReader.read(f));
        assertTrue(e.getMessage().startsWith(f.toString()), e.getMessage());
        assertFalse(e.getMessage().contains("\n"), e.getMessage());
    }

    /**
     * A file whose directory comes first (as in Cloud-Optimized GeoTIFFs; written here by the TIFF
     * library's own writer) cut short, as by an interrupted download: the message names the file and
     * the block that is missing.
     */
    @ParameterizedTest(name = "{0} % kept")
    @CsvSource({"50", "90", "99"})
    void aDownloadCutShortIsRefusedNamingTheFile(int keepPercent) throws IOException {
        int n = 121;
        mil.nga.tiff.Rasters rasters = new mil.nga.tiff.Rasters(n, n, 1, mil.nga.tiff.FieldType.SSHORT);
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                rasters.setFirstPixelSample(c, r, (short) plane(r, c));
            }
        }
        mil.nga.tiff.FileDirectory d = new mil.nga.tiff.FileDirectory();
        d.setImageWidth(n);
        d.setImageHeight(n);
        d.setBitsPerSample(16);
        d.setCompression(mil.nga.tiff.util.TiffConstants.COMPRESSION_DEFLATE);
        d.setPhotometricInterpretation(1);
        d.setSamplesPerPixel(1);
        d.setRowsPerStrip(8);
        d.setPlanarConfiguration(1);
        d.setSampleFormat(mil.nga.tiff.util.TiffConstants.SAMPLE_FORMAT_SIGNED_INT);
        d.setWriteRasters(rasters);
        d.setModelPixelScale(java.util.List.of(D, D, 0.0));
        d.setModelTiepoint(java.util.List.of(0.0, 0.0, 0.0, 8.0, 47.0, 0.0));
        d.setUnsignedIntegerListEntryValue(mil.nga.tiff.FieldTagType.GeoKeyDirectory,
                java.util.List.of(1, 1, 0, 2, 1024, 0, 1, 2, 1025, 0, 1, 2));
        byte[] full = mil.nga.tiff.TiffWriter.writeTiffToBytes(new mil.nga.tiff.TIFFImage(d));
        Path f = dir.resolve("N46E008.tif");
        Files.write(f, full);
        assertEquals(plane(60, 70), GeoTiffReader.read(f).heightMetres(60, 70), "the whole file reads");
        Files.write(f, Arrays.copyOf(full, full.length * keepPercent / 100));
        DemException e = assertThrows(DemException.class, () -> GeoTiffReader.read(f));
        assertTrue(e.getMessage().matches(java.util.regex.Pattern.quote(f.toString())
                + ": image block \\d+ lies beyond the end of the file \\(\\d+ bytes; truncated\\?\\)"), e.getMessage());
    }

    @Test
    void anUnsupportedCompressionIsRefusedByName() throws IOException {
        Spec s = srtmLike(false).withCompressionCodeWritten(50000);
        Path f = GeoTiffTestFiles.write(dir.resolve("N46E008.tif"), s, GeoTiffReaderTest::plane);
        DemException e = assertThrows(DemException.class, () -> GeoTiffReader.read(f));
        assertEquals(f + " uses TIFF compression 50000 (ZSTD), which dempano cannot decode; recompress it, "
                + "e.g. gdal_translate -co COMPRESS=DEFLATE", e.getMessage());
    }

    @Test
    void aBigTiffIsRefusedByName() throws IOException {
        Path f = dir.resolve("N46E008.tif");
        Files.write(f, new byte[] {'I', 'I', 43, 0, 8, 0, 0, 0, 16, 0, 0, 0, 0, 0, 0, 0});
        DemException e = assertThrows(DemException.class, () -> GeoTiffReader.read(f));
        assertTrue(e.getMessage().startsWith(f + " is a BigTIFF, which dempano cannot read"), e.getMessage());
    }

    @Test
    void implausibleHeightsWithoutNodataTagAreRefused() throws IOException {
        Path f = GeoTiffTestFiles.write(dir.resolve("N46E008.tif"), srtmLike(false),
                (r, c) -> r == 7 && c == 9 ? -32768 : plane(r, c));
        DemException e = assertThrows(DemException.class, () -> GeoTiffReader.read(f));
        assertTrue(e.getMessage().startsWith(f + ": implausible height -32768 m at row 7, column 9"), e.getMessage());
    }

    @Test
    void cloudOptimizedOverviewsAreSkipped() throws IOException {
        Spec s = srtmLike(false).withCompression(DEFLATE, 2).withLayout(32, 0, ByteOrder.LITTLE_ENDIAN).withOverview();
        Path f = GeoTiffTestFiles.write(dir.resolve("N46E008.tif"), s, GeoTiffReaderTest::plane);
        HgtTile t = GeoTiffReader.read(f);
        assertEquals(plane(60, 61), t.heightMetres(60, 61));
        assertEquals(plane(120, 120), t.heightMetres(120, 120));
    }

    @Test
    void modelTransformationGeoreferencingEqualsTiepointAndScale() throws IOException {
        Path a = GeoTiffTestFiles.write(dir.resolve("N46E008.tif"), srtmLike(false).withTransformation(), GeoTiffReaderTest::plane);
        HgtTile t = GeoTiffReader.read(a);
        for (int r = 0; r < 121; r += 7) {
            for (int c = 0; c < 121; c += 5) {
                assertEquals(plane(r, c), t.heightMetres(r, c));
            }
        }
    }

    @Test
    void verticalDatumFromKeysElseNamingElseUnknown() throws IOException {
        Path a = GeoTiffTestFiles.write(dir.resolve("N46E008.tif"), srtmLike(false).withCrs(2, 4326, 5773), GeoTiffReaderTest::plane);
        assertEquals(DemContribution.EGM96, GeoTiffReader.read(a).verticalDatum());
        Path b = GeoTiffTestFiles.write(dir.resolve("N46E008_b.tif"), srtmLike(false).withCrs(2, 4326, 3855), GeoTiffReaderTest::plane);
        assertEquals(DemContribution.EGM2008, GeoTiffReader.read(b).verticalDatum());
        Path c = GeoTiffTestFiles.write(dir.resolve("N46E008_c.tif"), srtmLike(false), GeoTiffReaderTest::plane);
        assertEquals(DemContribution.UNKNOWN, GeoTiffReader.read(c).verticalDatum());
        assertEquals("unknown", GeoTiffReader.read(c).contributions().get(0).verticalDatum());
    }

    /** The first image directory's offset in a little-endian TIFF. */
    private static int firstDirectory(byte[] b) {
        return java.nio.ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN).getInt(4);
    }

    /** Sets a SHORT tag's value in the first directory of a little-endian TIFF (a file that lies about itself). */
    private static byte[] withShortTag(byte[] b, int tag, int value) {
        java.nio.ByteBuffer buf = java.nio.ByteBuffer.wrap(b.clone()).order(ByteOrder.LITTLE_ENDIAN);
        int at = firstDirectory(b), n = buf.getShort(at) & 0xffff;
        for (int i = 0; i < n; i++) {
            int entry = at + 2 + 12 * i;
            if ((buf.getShort(entry) & 0xffff) == tag) {
                assertEquals(3, buf.getShort(entry + 2), "tag " + tag + " is a SHORT");
                buf.putShort(entry + 8, (short) value);
                return buf.array();
            }
        }
        throw new AssertionError("no tag " + tag);
    }

    /**
     * Hostile files (a 282-byte GeoTIFF looping its directories grew the process to 18 GB; one declaring 46 341² pixels
     * overflowed the heights' array; one declaring 30 000² took 3.7 GB before it was refused; a 1 MB Deflate strip
     * inflated to 1 GB): each refused at once, naming the file and what is wrong.
     */
    @Test
    void filesThatLieAboutTheirSizeOrLoopAreRefusedBeforeAnythingLargeIsAllocated() throws IOException {
        byte[] good = GeoTiffTestFiles.bytes(srtmLike(false).withLayout(0, 121, ByteOrder.LITTLE_ENDIAN), GeoTiffReaderTest::plane);
        // The directory names itself as the next one.
        byte[] loop = good.clone();
        int first = firstDirectory(good), entries = java.nio.ByteBuffer.wrap(good).order(ByteOrder.LITTLE_ENDIAN).getShort(first);
        java.nio.ByteBuffer.wrap(loop).order(ByteOrder.LITTLE_ENDIAN).putInt(first + 2 + 12 * entries, first);
        Path f = Files.write(dir.resolve("N46E008.tif"), loop);
        DemException e = assertThrows(DemException.class, () -> GeoTiffReader.read(f));
        assertEquals(f + " is a corrupt TIFF file: its chain of image directories loops back to the one at byte " + first,
                e.getMessage());
        // More pixels than one file may hold (an int overflow before).
        Files.write(f, withShortTag(withShortTag(good, 256, 46341), 257, 46341));
        e = assertThrows(DemException.class, () -> GeoTiffReader.read(f));
        assertTrue(e.getMessage().startsWith(f + " declares 46341 × 46341 pixels, more than dempano reads from one file (268 M;"),
                e.getMessage());
        // Fewer, but more than its one strip holds, raw or compressed: refused before the heights are allocated.
        for (int compression : new int[] {NONE, DEFLATE, LZW}) {
            byte[] one = GeoTiffTestFiles.bytes(srtmLike(false).withCompression(compression, 1)
                    .withLayout(0, 121, ByteOrder.LITTLE_ENDIAN), GeoTiffReaderTest::plane);
            Files.write(f, withShortTag(withShortTag(withShortTag(one, 256, 15000), 257, 15000), 278, 15000));
            e = assertThrows(DemException.class, () -> GeoTiffReader.read(f));
            assertTrue(e.getMessage().matches(java.util.regex.Pattern.quote(f + ": image block 0 holds ") + "\\d+ bytes, 450000000 expected.* "
                    + java.util.regex.Pattern.quote("for its 15000 × 15000 pixels (truncated or corrupt file, or not the 15000 × 15000 pixels it declares?)")),
                    compression + ": " + e.getMessage());
        }
        // An empty GDAL_NODATA (only its closing NUL): the library failed on it with an index out of bounds.
        Files.write(f, GeoTiffTestFiles.bytes(srtmLike(false).withNodata(""), GeoTiffReaderTest::plane));
        e = assertThrows(DemException.class, () -> GeoTiffReader.read(f));
        assertEquals(f + " is a corrupt TIFF file: its text tag 42113 (GDAL_NODATA) is empty (no characters before its closing NUL)",
                e.getMessage());
        // A Deflate strip holding more than its block: 121 rows of data in a strip declared 60 rows high.
        byte[] deflated = GeoTiffTestFiles.bytes(srtmLike(false).withCompression(DEFLATE, 1)
                .withLayout(0, 121, ByteOrder.LITTLE_ENDIAN), GeoTiffReaderTest::plane);
        Files.write(f, withShortTag(withShortTag(deflated, 257, 60), 278, 60));
        e = assertThrows(DemException.class, () -> GeoTiffReader.readGrid(f));
        assertEquals(f + ": image block 0 decompresses to more than the 14520 bytes of its 121 × 60 pixels (corrupt file, "
                + "or a decompression bomb)", e.getMessage());
    }

    /**
     * A file covering part of its tile, even without its centre, is read with the rest void (a regional DEM before
     * SRTM in the sources); one reaching beyond its tile is read for that tile with a warning.
     */
    @Test
    void aFileCoveringPartOfItsTileIsReadAndOneReachingBeyondItIsReadWithAWarning() throws IOException {
        // 46.0…46.4 N, 8.6…9.0 E: the south-east corner, without the tile's centre.
        Path part = GeoTiffTestFiles.write(dir.resolve("N46E008.tif"), GeoTiffTestFiles.geographic(49, 49, 8.6, 46.4, D, D, true),
                (r, c) -> 700 + r + c);
        HgtTile t = GeoTiffReader.read(part);
        assertEquals(700 + 12 + 24, t.heightAt(46.3, 8.8), 1e-3, "a height in the part covered");
        assertTrue(t.isFilledVoid(60, 60), "the centre is a void (filled, or the next source's)");
        assertFalse(t.isFilledVoid(96, 96), "a sample of the part covered is data");
        assertTrue(t.voids().voidCells() > 121 * 121 / 2, "most of the tile is void: " + t.voids());
        // Two degrees wide under a one-degree name.
        Path wide = GeoTiffTestFiles.write(dir.resolve("N46E008_wide.tif"), GeoTiffTestFiles.geographic(241, 121, 8, 47, D, D, true),
                GeoTiffReaderTest::plane);
        HgtTile w = GeoTiffReader.toTile(GeoTiffReader.readGrid(wide), TileId.of(46, 8));
        assertEquals(plane(60, 120), w.heightMetres(60, 120), "the tile's own part");
        assertTrue(w.warnings().stream().anyMatch(m -> m.startsWith(wide + " reaches beyond its tile N46E008 (its pixels cover "
                + "latitude 46.0000…47.0000°, longitude 8.0000…10.0000°): only N46E008 is read from it")), w.warnings().toString());
        // Only the edge shared with the tile named: refused (a file named for its neighbour).
        Path edge = GeoTiffTestFiles.write(dir.resolve("N46E008_edge.tif"), GeoTiffTestFiles.geographic(121, 121, 9, 47, D, D, true),
                GeoTiffReaderTest::plane);
        DemException e = assertThrows(DemException.class, () -> GeoTiffReader.toTile(GeoTiffReader.readGrid(edge), TileId.of(46, 8)));
        assertTrue(e.getMessage().startsWith(edge + " is named for tile N46E008 but its pixels cover"), e.getMessage());
    }

    @Test
    void aFileNamedForAnotherTileIsRefused() throws IOException {
        Path f = GeoTiffTestFiles.write(dir.resolve("N45E008.tif"), srtmLike(false), GeoTiffReaderTest::plane);
        DemException e = assertThrows(DemException.class, () -> GeoTiffReader.read(f));
        assertTrue(e.getMessage().startsWith(f + " is named for tile N45E008 but its pixels cover latitude 46.0000…47.0000°"),
                e.getMessage());
    }

    @Test
    void aCoarserOrFinerGridIsResampledBilinearly() throws IOException {
        // 1/90° pixels (40″), centres offset from the tile edges by a third of a pixel: every tile sample is
        // interpolated; heights linear in lat/lon come out exact.
        double d = 1.0 / 90, lon0 = 7.9, lat0 = 47.1;
        Spec s = GeoTiffTestFiles.geographic(120, 120, lon0 + d / 3, lat0 - d / 3, d, d, false).withType(SampleType.FLOAT32);
        Path f = GeoTiffTestFiles.write(dir.resolve("N46E008.tif"), s,
                (r, c) -> 1500 + 700 * (lat0 - d / 3 - r * d - 46) + 300 * (lon0 + d / 3 + c * d - 8));
        HgtTile t = GeoTiffReader.read(f);
        assertEquals(91, t.samplesPerSide());
        for (int r = 0; r < 91; r += 3) {
            for (int c = 0; c < 91; c += 3) {
                double lat = 47 - r / 90.0, lon = 8 + c / 90.0;
                assertEquals(1500 + 700 * (lat - 46) + 300 * (lon - 8), t.heightMetres(r, c), 2e-3, r + ", " + c);
            }
        }
        assertNotEquals(0, t.heightMetres(0, 0));
    }
}

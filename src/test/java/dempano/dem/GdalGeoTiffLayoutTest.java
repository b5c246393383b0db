package dempano.dem;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.SharedData;
import dempano.panorama.Panorama;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Real SRTM3 tiles from ../shared/dem converted at run time by GDAL's own tools (gdal_translate,
 * gdalwarp) into every GeoTIFF layout a user is likely to bring: int16/int32/float32 samples;
 * uncompressed, LZW and Deflate with the horizontal (2) and floating-point (3) predictors; strips and
 * tiles; Cloud-Optimized GeoTIFFs with overviews; voids as other nodata values (−9999, NaN) or none;
 * PixelIsPoint and PixelIsArea. The independent truth is the .hgt itself, read by
 * {@link HgtReader}: every layout must give the same samples and void mask, bit for bit, and a
 * panorama rendered from one of them must equal the .hgt's pixel for pixel. Without GDAL the tests
 * are skipped locally and fail under CI (see {@link Gdal}).
 */
class GdalGeoTiffLayoutTest {
    @TempDir
    Path dir;

    private static final String TILED = "-co TILED=YES -co BLOCKXSIZE=256 -co BLOCKYSIZE=256";

    /** Name, tile, gdal_translate options (split on spaces). */
    static Stream<Arguments> translateLayouts() {
        return Stream.of(
                Arguments.of("int16 uncompressed striped", "N46E008", "-ot Int16 -co COMPRESS=NONE"),
                Arguments.of("int16 LZW striped", "N46E008", "-ot Int16 -co COMPRESS=LZW"),
                Arguments.of("int16 LZW tiled", "N43E006", "-ot Int16 -co COMPRESS=LZW " + TILED),
                Arguments.of("int16 DEFLATE predictor 2 striped", "N46E008", "-ot Int16 -co COMPRESS=DEFLATE -co PREDICTOR=2"),
                Arguments.of("int16 DEFLATE predictor 2 tiled, big-endian", "N43E006",
                        "-ot Int16 -co COMPRESS=DEFLATE -co PREDICTOR=2 -co ENDIANNESS=BIG " + TILED),
                Arguments.of("int32 uncompressed tiled", "N46E008", "-ot Int32 " + TILED),
                Arguments.of("int32 LZW predictor 2 striped", "N46E008", "-ot Int32 -co COMPRESS=LZW -co PREDICTOR=2"),
                Arguments.of("int32 DEFLATE predictor 2 tiled", "N43E006", "-ot Int32 -co COMPRESS=DEFLATE -co PREDICTOR=2 " + TILED),
                Arguments.of("float32 uncompressed striped", "N46E008", "-ot Float32"),
                Arguments.of("float32 LZW predictor 3 striped", "N46E008", "-ot Float32 -co COMPRESS=LZW -co PREDICTOR=3"),
                Arguments.of("float32 DEFLATE predictor 3 tiled", "N46E008",
                        "-ot Float32 -co COMPRESS=DEFLATE -co PREDICTOR=3 " + TILED),
                // Not with predictor 3: GDAL 3.6.2 on libtiff 4.5.0 writes big-endian predictor-3 floats byte-swapped
                // (gdallocationinfo reads its own N43E006 corner back as 5.9e-39, not 729 m).
                Arguments.of("float32 DEFLATE tiled, big-endian", "N43E006",
                        "-ot Float32 -co COMPRESS=DEFLATE -co ENDIANNESS=BIG " + TILED),
                Arguments.of("float32 DEFLATE predictor 2 striped", "N46E008", "-ot Float32 -co COMPRESS=DEFLATE -co PREDICTOR=2"),
                Arguments.of("COG int16 DEFLATE predictor, overviews", "N46E008", "-of COG -ot Int16 -co COMPRESS=DEFLATE -co PREDICTOR=YES"),
                Arguments.of("COG float32 LZW predictor, overviews", "N46E008", "-of COG -ot Float32 -co COMPRESS=LZW -co PREDICTOR=YES"),
                Arguments.of("COG int16 uncompressed, no overviews", "N43E006", "-of COG -ot Int16 -co COMPRESS=NONE -co OVERVIEWS=NONE"),
                Arguments.of("PixelIsArea int16 DEFLATE", "N46E008", "-ot Int16 -co COMPRESS=DEFLATE -mo AREA_OR_POINT=Area"),
                Arguments.of("PixelIsArea float32 COG", "N46E008", "-of COG -ot Float32 -mo AREA_OR_POINT=Area"),
                Arguments.of("PixelIsPoint float32 tiled", "N43E006", "-ot Float32 -mo AREA_OR_POINT=Point " + TILED),
                // Heights stored scaled, with GDAL's band scale and offset (GDAL_METADATA): read as metres they were
                // 10 times too high, or 500 m too high (a hostile test: scale 2 rendered at half the height, silently).
                Arguments.of("int32 decimetres, scale 0.1", "N46E008", "-ot Int32 -scale 0 1000 0 10000 -a_scale 0.1"),
                Arguments.of("int16 offset -500", "N43E006", "-ot Int16 -scale 0 1000 500 1500 -a_offset -500"));
    }

    @ParameterizedTest(name = "{0} ({1})")
    @MethodSource("translateLayouts")
    void gdalTranslateLayoutLoadsToTheHgtSamples(String layout, String tile, String options) throws IOException {
        Path hgt = SharedData.demFile(tile + ".hgt");
        Path tif = Gdal.translate(hgt, dir.resolve(tile + ".tif"), options.split(" "));
        assertSameTile(HgtReader.read(hgt), GeoTiffReader.read(tif), layout);
    }

    /**
     * Voids written as another nodata value than the .hgt's −32768 (gdalwarp onto the identical grid with
     * nearest-neighbour resampling copies every valid sample and writes voids as the new nodata value), or
     * a float32 tile whose voids are NaN.
     */
    static Stream<Arguments> nodataLayouts() {
        return Stream.of(
                Arguments.of("int16 nodata -9999", "-ot Int16 -dstnodata -9999 -co COMPRESS=DEFLATE"),
                Arguments.of("int32 nodata 99999", "-ot Int32 -dstnodata 99999 -co COMPRESS=LZW"),
                Arguments.of("float32 nodata -9999 predictor 3", "-ot Float32 -dstnodata -9999 -co COMPRESS=DEFLATE -co PREDICTOR=3"),
                Arguments.of("float32 nodata NaN tiled", "-ot Float32 -dstnodata nan -co TILED=YES"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("nodataLayouts")
    void voidsAsAnotherNodataValueStayVoids(String layout, String options) throws IOException {
        Path hgt = SharedData.demFile("N46E008.hgt");
        List<String> a = new ArrayList<>(List.of("-r", "near", "-srcnodata", "-32768"));
        a.addAll(List.of(options.split(" ")));
        Path tif = Gdal.warp(hgt, dir.resolve("N46E008.tif"), a.toArray(String[]::new));
        String info = Gdal.run("gdalinfo", tif.toString());
        String value = layout.replaceAll(".*nodata (\\S+).*", "$1");
        assertTrue(info.toLowerCase(java.util.Locale.ROOT).contains("nodata value=" + value.toLowerCase(java.util.Locale.ROOT)),
                "gdalwarp did not write nodata " + value + ":\n" + info);
        HgtTile fromHgt = HgtReader.read(hgt);
        assertTrue(fromHgt.voids().voidCells() > 100_000, "N46E008 has voids to test with");
        assertSameTile(fromHgt, GeoTiffReader.read(tif), layout);
    }

    /**
     * A Copernicus-style COG (named {@code Copernicus_DSM_COG_30_N43_00_E006_00_DEM.tif}, 1200 × 1200
     * pixels from the north-west corner: no southern row, no eastern column) with its eastern neighbour
     * beside it: the tile is found under its Copernicus name, the eastern column is the neighbour's first
     * (which differs from N43E006.hgt's own eastern column in 202 samples, by up to 174 m: SRTM tiles do
     * not always agree on their shared edge), the rest but the southern row (no southern neighbour, so
     * repeated) equals the .hgt.
     */
    @Test
    void copernicusNamedCogsAreRecognisedAndJoined() throws IOException {
        Path west = SharedData.demFile("N43E006.hgt"), east = SharedData.demFile("N43E007.hgt");
        Path tifs = Files.createDirectory(dir.resolve("cop"));
        String[] crop = {"-of", "COG", "-srcwin", "0", "0", "1200", "1200", "-co", "COMPRESS=DEFLATE", "-co", "PREDICTOR=YES"};
        Gdal.translate(west, tifs.resolve("Copernicus_DSM_COG_30_N43_00_E006_00_DEM.tif"), crop);
        Gdal.translate(east, tifs.resolve("Copernicus_DSM_COG_30_N43_00_E007_00_DEM.tif"), crop);
        DemDirectory d = new DemDirectory(tifs);
        assertEquals(List.of(TileId.of(43, 6), TileId.of(43, 7)), List.copyOf(d.files().keySet()));
        HgtTile fromTif = d.tile(TileId.of(43, 6)).orElseThrow();
        HgtTile fromHgt = HgtReader.read(west), eastHgt = HgtReader.read(east);
        assertEquals(1201, fromTif.samplesPerSide());
        int n = 1201, compared = 0;
        for (int r = 0; r < n - 1; r++) {
            for (int c = 0; c < n; c++) {
                HgtTile truth = c < n - 1 ? fromHgt : eastHgt;
                int tc = c < n - 1 ? c : 0;
                if (!truth.isFilledVoid(r, tc)) {
                    assertEquals(truth.heightMetres(r, tc), fromTif.heightMetres(r, c), "sample " + r + ", " + c);
                    compared++;
                }
                assertEquals(truth.isFilledVoid(r, tc), fromTif.isFilledVoid(r, c), "void at " + r + ", " + c);
            }
        }
        assertTrue(compared > 1_400_000, compared + " samples compared");
        for (int c = 0; c < n; c++) {
            assertEquals(fromTif.heightMetres(n - 2, c), fromTif.heightMetres(n - 1, c), "repeated southern row, column " + c);
        }
        assertEquals(DemContribution.EGM2008, fromTif.verticalDatum()); // the Copernicus naming
    }

    /** A short panorama from a GDAL-made tiled, predictor-3 float32 GeoTIFF equals the .hgt's, bit for bit. */
    @Test
    void aPanoramaFromAGdalGeoTiffEqualsTheHgtsBitForBit() throws IOException {
        Path hgt = SharedData.demFile("N46E008.hgt");
        Path tifs = Files.createDirectory(dir.resolve("tif"));
        Gdal.translate(hgt, tifs.resolve("N46E008.tif"), ("-ot Float32 -co COMPRESS=DEFLATE -co PREDICTOR=3 " + TILED).split(" "));
        // Above the Grimsel: voids of N46E008 (the Aar glaciers) lie in view.
        PanoramaRequest req = PanoramaRequest.at(46.57, 8.33).withRangeMetres(15_000).withPixelsPerDegree(2).withColour(true);
        Panorama a, b;
        try (PanoramaRenderer r = PanoramaRenderer.openReference(new DemDirectory(hgt.getParent()))) {
            a = r.render(req);
        }
        try (PanoramaRenderer r = PanoramaRenderer.openReference(new DemDirectory(tifs))) {
            b = r.render(req);
        }
        assertEquals(a.widthPx(), b.widthPx());
        assertEquals(a.heightPx(), b.heightPx());
        assertArrayEquals(a.distanceArray(), b.distanceArray(), "distances");
        int[] pa = new int[a.widthPx() * a.heightPx()], pb = new int[pa.length];
        int terrain = 0;
        for (int y = 0; y < a.heightPx(); y++) {
            for (int x = 0; x < a.widthPx(); x++) {
                pa[y * a.widthPx() + x] = a.argb(x, y);
                pb[y * a.widthPx() + x] = b.argb(x, y);
                terrain += Float.isFinite(a.distanceMetres(x, y)) ? 1 : 0;
            }
        }
        assertArrayEquals(pa, pb, "colours");
        assertTrue(terrain > pa.length / 4, "the panorama shows terrain: " + terrain + " of " + pa.length + " pixels");
    }

    /** Same samples (bit for bit) and the same void mask. */
    /**
     * A GeoTIFF holding the western 700 of a tile's 1201 columns (a hostile test): its column 700 repeated column 699
     * instead of being void, and as the first of two DEM folders that false column was blended into the second's
     * heights up to 50 m off, still 3 m some 8 km in. Now the samples beyond the file are voids and the second folder,
     * the whole tile, fills them with its own heights exactly.
     */
    @Test
    void aGeoTiffCoveringPartOfItsTileLeavesTheRestToTheNextSource() throws IOException {
        Path hgt = SharedData.demFile("N43E006.hgt");
        Path part = Files.createDirectories(dir.resolve("part")), whole = Files.createDirectories(dir.resolve("whole"));
        Gdal.translate(hgt, part.resolve("N43E006.tif"), "-srcwin", "0", "0", "700", "1201");
        Files.copy(hgt, whole.resolve("N43E006.hgt"));
        HgtTile ref = HgtReader.read(hgt), alone = GeoTiffReader.read(part.resolve("N43E006.tif"));
        for (int r = 0; r < 1201; r++) {
            if (!ref.isFilledVoid(r, 699)) {
                assertEquals(ref.heightMetres(r, 699), alone.heightMetres(r, 699), "column 699, row " + r);
            }
            assertTrue(alone.isFilledVoid(r, 700), "column 700 lies beyond the file: a void, row " + r);
        }
        List<String> warnings = new ArrayList<>();
        DemSource both = PriorityDem.open(List.of(part, whole), DemFill.DEFAULT, warnings::add);
        assertSameHeights(ref, both.tile(TileId.of(43, 6)).orElseThrow(), "the part, then the whole tile");
    }

    /** Every sample's height equal (voids aside: the merged tile has none where the second source has data). */
    static void assertSameHeights(HgtTile expected, HgtTile actual, String what) {
        int n = expected.samplesPerSide();
        assertEquals(n, actual.samplesPerSide(), what);
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                if (!expected.isFilledVoid(r, c)) {
                    assertEquals(expected.heightMetres(r, c), actual.heightMetres(r, c), what + ": sample " + r + ", " + c);
                }
            }
        }
    }

    static void assertSameTile(HgtTile expected, HgtTile actual, String what) {
        int n = expected.samplesPerSide();
        assertEquals(n, actual.samplesPerSide(), what + ": samples per side");
        assertEquals(expected.voids().voidCells(), actual.voids().voidCells(), what + ": void samples");
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                assertEquals(expected.isFilledVoid(r, c), actual.isFilledVoid(r, c), what + ": void at " + r + ", " + c);
                if (Float.floatToRawIntBits(expected.heightMetres(r, c)) != Float.floatToRawIntBits(actual.heightMetres(r, c))) {
                    assertEquals(expected.heightMetres(r, c), actual.heightMetres(r, c), what + ": sample " + r + ", " + c);
                }
            }
        }
    }
}

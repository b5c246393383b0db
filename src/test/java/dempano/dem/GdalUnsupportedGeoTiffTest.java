package dempano.dem;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.SharedData;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.stream.Stream;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Every GeoTIFF variant dempano cannot read correctly, made by GDAL's tools from a real tile, is
 * refused with one message that names the file and the property (and no height is ever read from it
 * in the wrong place or unit). Without GDAL the tests are skipped locally and fail under CI (see {@link Gdal}).
 */
class GdalUnsupportedGeoTiffTest {
    @TempDir
    Path dir;

    private static final String GCPS = "-a_srs EPSG:4326 -gcp 0 0 8 47 -gcp 1200 0 9 47 -gcp 0 1200 8 46 -gcp 1200 1200 9 46";

    /** Variant, tool (translate or warp), its options, words the message must hold (lower case, '|' separated). */
    static Stream<Arguments> variants() {
        return Stream.of(
                Arguments.of("projected CRS (UTM 32N)", "warp", "-t_srs EPSG:32632 -tr 90 90", "projected crs|epsg:32632"),
                Arguments.of("projected CRS (Swiss LV95)", "warp", "-t_srs EPSG:2056 -tr 90 90", "projected crs|epsg:2056"),
                Arguments.of("two bands", "translate", "-b 1 -b 1", "2 bands"),
                Arguments.of("two bands, band-interleaved", "translate", "-b 1 -b 1 -co INTERLEAVE=BAND", "2 bands"),
                Arguments.of("JPEG compression", "translate", "-ot Byte -scale -co COMPRESS=JPEG", "compression 7|jpeg"),
                Arguments.of("ZSTD compression", "translate", "-co COMPRESS=ZSTD", "compression 50000|zstd"),
                Arguments.of("LERC compression", "translate", "-ot Float32 -co COMPRESS=LERC", "compression 34887|lerc"),
                Arguments.of("complex samples", "translate", "-ot CInt16", "sample type|complex integer"),
                Arguments.of("complex float samples", "translate", "-ot CFloat32", "sample type|complex float"),
                Arguments.of("64-bit integer samples", "translate", "-ot Int64", "sample type|64-bit signed integer"),
                Arguments.of("16-bit float samples", "translate", "-ot Float32 -co NBITS=16", "sample type|16-bit float"),
                Arguments.of("1-bit samples", "translate", "-ot Byte -scale -co NBITS=1", "sample type|1-bit"),
                Arguments.of("rotated geotransform", "rotate", "", "rotated or sheared"),
                Arguments.of("control points", "translate", GCPS, "4 control points"),
                Arguments.of("no georeferencing", "translate", "-co PROFILE=BASELINE", "no geotiff georeferencing"),
                Arguments.of("BigTIFF", "translate", "-co BIGTIFF=YES", "bigtiff"),
                Arguments.of("prime meridian of Paris", "translate", "-a_srs +proj=longlat +ellps=WGS84 +pm=paris",
                        "prime meridian|2.337"),
                Arguments.of("geographic CRS on another datum (ED50)", "translate", "-a_srs EPSG:4230", "datum|epsg:4230|not wgs 84"),
                Arguments.of("heights in US survey feet", "translate", "-a_srs EPSG:4326+6360", "feet|navd88 height (ftus)"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void isRefusedNamingTheFileAndTheProperty(String variant, String tool, String options, String words) throws IOException {
        Path hgt = SharedData.demFile("N46E008.hgt");
        Path tif = dir.resolve("N46E008.tif");
        String[] opts = options.isEmpty() ? new String[0] : options.startsWith("-a_srs +proj")
                ? new String[] {"-a_srs", options.substring("-a_srs ".length())} : options.split(" ");
        switch (tool) {
            case "warp" -> Gdal.warp(hgt, tif, opts);
            case "translate" -> Gdal.translate(hgt, tif, opts);
            default -> { // a VRT with a rotated geotransform, written out as a GeoTIFF (GDAL writes a ModelTransformation)
                Path vrt = Gdal.translate(hgt, dir.resolve("rot.vrt"), "-of", "VRT");
                String x = Files.readString(vrt).replaceAll("<GeoTransform>[^<]*</GeoTransform>",
                        "<GeoTransform>7.9995833, 8.333e-4, 1e-5, 47.0004167, 1e-5, -8.333e-4</GeoTransform>");
                Files.writeString(vrt, x);
                Gdal.translate(vrt, tif);
            }
        }
        DemException e = assertThrows(DemException.class, () -> GeoTiffReader.read(tif), variant + " was read");
        String m = e.getMessage().toLowerCase(Locale.ROOT);
        assertTrue(m.contains(tif.toString().toLowerCase(Locale.ROOT)), "the message names the file: " + e.getMessage());
        for (String w : words.split("\\|")) {
            assertTrue(m.contains(w), "the message says '" + w + "': " + e.getMessage());
        }
        assertTrue(!m.contains("\n") && !m.contains("exception"), "one plain line: " + e.getMessage());
    }
}

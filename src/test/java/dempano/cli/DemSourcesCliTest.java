package dempano.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import dempano.dem.GeoTiffCliFixtures;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * GeoTIFF DEMs and several {@code --dem-dir} in priority through the CLI (issue 20): the sources
 * that served each tile and their vertical datums land in P.json; bad GeoTIFFs fail with one line.
 * Renders with the CPU reference renderer at 2 pixels per degree.
 */
class DemSourcesCliTest {
    @TempDir
    Path tmp;

    private String[] render(Path out, String... demDirs) {
        java.util.List<String> argv = new java.util.ArrayList<>(java.util.List.of("--lat", "43.5", "--lon", "7.5",
                "--range-km", "20", "--ppd", "2", "--renderer", "reference", "--out", out.resolve("p").toString()));
        for (String d : demDirs) {
            argv.addAll(java.util.List.of("--dem-dir", d));
        }
        return MainTest.run(argv.toArray(String[]::new));
    }

    @Test
    void aCopernicusTileWithAHoleFilledFromSrtmIsReportedInTheMetadata() throws IOException {
        Path cop = Files.createDirectory(tmp.resolve("cop")), srtm = Files.createDirectory(tmp.resolve("srtm"));
        Path out = Files.createDirectory(tmp.resolve("out"));
        Path tif = GeoTiffCliFixtures.copernicusWithHole(cop, 43, 7);
        Path hgt = DemInputCliTest.tile(srtm, "N43E007.hgt");
        String[] r = render(out, cop.toString(), srtm.toString());
        assertEquals("0", r[0], r[1]);
        JsonObject json = JsonParser.parseString(Files.readString(out.resolve("p.json"))).getAsJsonObject();
        JsonArray sources = json.getAsJsonArray("demSources");
        assertEquals(2, sources.size(), sources.toString());
        JsonObject a = sources.get(0).getAsJsonObject(), b = sources.get(1).getAsJsonObject();
        assertEquals("N43E007", a.get("tile").getAsString());
        assertEquals(tif.toString(), a.get("source").getAsString());
        assertEquals("EGM2008", a.get("verticalDatum").getAsString());
        assertEquals(1201L * 1201 - GeoTiffCliFixtures.HOLE_SAMPLES, a.get("samples").getAsLong());
        assertEquals(hgt.toString(), b.get("source").getAsString());
        assertEquals("EGM96", b.get("verticalDatum").getAsString());
        assertEquals(GeoTiffCliFixtures.HOLE_SAMPLES, b.get("samples").getAsLong());
        assertTrue(r[1].contains(cop + ", then " + srtm), r[1]);
        assertTrue(r[1].contains("warning: the DEM heights refer to different vertical datums [EGM2008, EGM96]"), r[1]);
    }

    @Test
    void aTruncatedGeoTiffFailsWithOneLineNamingIt() throws IOException {
        Path cop = Files.createDirectory(tmp.resolve("cop")), out = Files.createDirectory(tmp.resolve("out"));
        Path tif = GeoTiffCliFixtures.copernicusWithHole(cop, 43, 7);
        byte[] b = Files.readAllBytes(tif);
        Files.write(tif, java.util.Arrays.copyOf(b, b.length / 3));
        String[] r = render(out, cop.toString());
        assertEquals("1", r[0], r[1]);
        assertTrue(r[1].contains("dempano: " + tif), r[1]);
        assertFalse(r[1].contains("\tat "), "no stack trace: " + r[1]);
    }

    @Test
    void aProjectedGeoTiffIsRefusedWithTheWayOut() throws IOException {
        Path dem = Files.createDirectory(tmp.resolve("utm")), out = Files.createDirectory(tmp.resolve("out"));
        Path tif = GeoTiffCliFixtures.projected(dem.resolve("N43E007.tif"));
        String[] r = render(out, dem.toString());
        assertEquals("1", r[0], r[1]);
        assertTrue(r[1].contains(tif + " is in a projected CRS (EPSG:32632); reproject it to geographic lat/lon, "
                + "e.g. with gdalwarp -t_srs EPSG:4326"), r[1]);
    }
}

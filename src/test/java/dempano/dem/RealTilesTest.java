package dempano.dem;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.SharedData;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Real SRTM3 tiles from ../shared/dem against surveyed summit heights and the tiles' documented properties. */
class RealTilesTest {
    // file, tile, documented min and max height (../shared/README.md), documented void share
    @ParameterizedTest
    @CsvSource({
            "N43E006.hgt, N43E006, -12, 1923",
            "N44W072.hgt, N44W072, -100, 1908",
            "N48E009.hgt, N48E009, 173, 977",
            "N00E010.hgt, N00E010, -100, 1100",
            "N19W155v2.3a.hgt.zip, N19W155, -100, 4207",
            "N22W160v2.3a.hgt.zip, N22W160, -100, 1598",
            "S16E166v2.3a.hgt.zip, S16E166, -100, 1879",
    })
    void readsRealTiles(String file, String tile, int min, int max) {
        HgtTile t = HgtReader.read(SharedData.demFile(file));
        assertEquals(tile, t.id().name());
        assertEquals(1201, t.samplesPerSide());
        float lo = Float.MAX_VALUE, hi = -Float.MAX_VALUE;
        for (int r = 0; r < 1201; r++) {
            for (int c = 0; c < 1201; c++) {
                float h = t.heightMetres(r, c);
                assertTrue(!Float.isNaN(h), "void left unfilled");
                lo = Math.min(lo, h);
                hi = Math.max(hi, h);
            }
        }
        assertTrue(lo >= min && hi <= max && hi > lo, "range " + lo + ".." + hi + " outside " + min + ".." + max);
    }

    @Test
    void alpineTileVoidsAreFilledAndReported() {
        HgtTile t = HgtReader.read(SharedData.demFile("N46E008.hgt"));
        double share = t.voids().voidCells() / (1201.0 * 1201.0);
        assertEquals(0.072, share, 0.005, "README: 7.2 % voids");
        assertTrue(t.voids().hasLargeRegion());
        float hi = 0;
        for (int r = 0; r < 1201; r++) {
            for (int c = 0; c < 1201; c++) {
                hi = Math.max(hi, t.heightMetres(r, c));
            }
        }
        // Filled voids interpolate: they cannot exceed the valid maximum (4173 m per README).
        assertTrue(hi <= 4173.0f, "max " + hi);
    }

    @Test
    void crimeaVoidsAreFilled() {
        HgtTile t = HgtReader.read(SharedData.demFile("N44E033.hgt"));
        assertEquals(852, t.voids().voidCells(), "README: 852 voids");
    }

    // Surveyed summits (lat, lon, height m): the 90 m DEM at the summit is lower by up to tens of metres.
    @ParameterizedTest
    @CsvSource({
            "N44W072.hgt, 44.2706, -71.3033, 1917, 25",  // Mount Washington
            "N46E008.hgt, 46.4314, 8.0942, 2927, 60",     // Eggishorn
            "N43E007.hgt, 43.992222, 7.093333, 1804, 60",  // Pointe de Quatre Cantons (alps.txt)
    })
    void summitHeights(String file, double lat, double lon, double surveyed, double tolerance) {
        Path dir = SharedData.demDir();
        SharedData.demFile(file);
        Mosaic m = Mosaic.around(new DemDirectory(dir), lat, lon, 5000, MissingTilePolicy.SEA_LEVEL);
        assertEquals(surveyed, m.heightAt(lat, lon), tolerance);
    }

    @Test
    void neighbouringRealTilesShareTheirEdge() {
        HgtTile w = HgtReader.read(SharedData.demFile("N48E009.hgt"));
        HgtTile e = HgtReader.read(SharedData.demFile("N48E010.hgt"));
        int equal = 0;
        for (int r = 0; r < 1201; r++) {
            if (w.heightMetres(r, 1200) == e.heightMetres(r, 0)) {
                equal++;
            }
        }
        assertTrue(equal > 1150, "shared column equal in " + equal + " of 1201 rows");
        Mosaic m = Mosaic.around(new DemDirectory(SharedData.demDir()), 48.5, 10.0, 20_000, MissingTilePolicy.ERROR);
        assertEquals(2401, m.cols());
        for (int r = 0; r < 1201; r++) {
            assertEquals(e.heightMetres(r, 5), m.sample(r, 1205), 0);
            assertEquals(w.heightMetres(r, 1195), m.sample(r, 1195), 0);
        }
    }
}

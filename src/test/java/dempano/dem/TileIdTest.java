package dempano.dem;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class TileIdTest {
    // file name, south edge, west edge, canonical name — truth: the SRTM naming convention (SW corner).
    @ParameterizedTest
    @CsvSource({
            "N46E008.hgt, 46, 8, N46E008",
            "n46e008.hgt, 46, 8, N46E008",
            "S16E166.hgt, -16, 166, S16E166",
            "S16E166v2.3a.hgt.zip, -16, 166, S16E166",
            "N19W155v2.3a.hgt.zip, 19, -155, N19W155",
            "N00W001.hgt, 0, -1, N00W001",
            "N00E000.hgt, 0, 0, N00E000",
            "S01W180.hgt, -1, -180, S01W180",
            "N89E179.hgt, 89, 179, N89E179",
            "S90W180.HGT, -90, -180, S90W180",
            "N46E008.tif, 46, 8, N46E008",
            "N46E008.hgt.gz, 46, 8, N46E008",
            "s16e166_dem.TIFF, -16, 166, S16E166",
            "Copernicus_DSM_COG_10_N46_00_E008_00_DEM.tif, 46, 8, N46E008",
            "Copernicus_DSM_COG_30_S16_00_W155_00_DEM.tif, -16, -155, S16W155",
    })
    void parsesNames(String file, int lat, int lon, String canonical) {
        TileId id = TileId.parseFileName(file);
        assertEquals(new TileId(lat, lon), id);
        assertEquals(canonical, id.name());
    }

    @ParameterizedTest
    @CsvSource({"N46E008.png", "Copernicus_DSM_COG_10_N46_00_E008_DEM.tif", "X46E008.hgt", "N4E008.hgt", "N46E08.hgt", "N90E000.hgt", "N10E180.hgt",
            "S91E000.hgt", "N10W181.hgt", "N46E008.zip", "N46E008.gz", "N46E008.hgt.bz2",
            // No tile is named by a south-west corner at S00 or W000 (they were read as N00 and E000).
            "S00E010.hgt", "N45W000.hgt", "s00w000.tif", "Copernicus_DSM_COG_10_S00_00_E010_00_DEM.tif"})
    void rejectsBadNames(String file) {
        DemException e = assertThrows(DemException.class, () -> TileId.parseFileName(file));
        assertTrue(e.getMessage().contains(file), e.getMessage());
    }

    // point, tile containing it; points on an edge belong to the tile north/east of the edge.
    @ParameterizedTest
    @CsvSource({
            "46.43, 8.09, N46E008",
            "46.0, 8.0, N46E008",
            "-15.5, 166.5, S16E166",
            "-0.0001, -0.0001, S01W001",
            "0.0, 0.0, N00E000",
            "10.5, 180.0, N10W180",
            "10.5, -180.0, N10W180",
            "10.5, 179.999, N10E179",
            "90.0, 0.5, N89E000",
    })
    void containing(double lat, double lon, String name) {
        assertEquals(name, TileId.containing(lat, lon).name());
    }

    @ParameterizedTest
    @CsvSource({"10, 180, N10W180", "10, 181, N10W179", "10, -181, N10E179", "10, 540, N10W180"})
    void ofWrapsLongitude(int lat, int lon, String name) {
        assertEquals(name, TileId.of(lat, lon).name());
    }

    @org.junit.jupiter.api.Test
    void recognisesTileFileNames() {
        assertTrue(TileId.isTileFileName("N43E006.hgt"));
        assertFalse(TileId.isTileFileName("SHA256SUMS"));
    }
}

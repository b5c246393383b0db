package dempano.summits;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.SharedData;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SummitReaderTest {
    @Test
    void ferrantiLinesGiveDegreesFromDms() {
        SummitList l = SummitReader.ferranti("t", "  7:25:12 45:08:25  1325  R0 E07 BA MONTE CURT\n"
                + "  8:05:39 46:25:53  2927  H1 B02 G5 EGGISHORN\n\n# comment\n", false);
        assertEquals(2, l.size());
        Summit s = l.summits().get(0);
        assertEquals("MONTE CURT", s.name());
        assertEquals(7 + 25 / 60.0 + 12 / 3600.0, s.lonDeg(), 1e-12);
        assertEquals(45 + 8 / 60.0 + 25 / 3600.0, s.latDeg(), 1e-12);
        assertEquals(1325, s.elevationMetres());
        assertEquals(-(71 + 18 / 60.0), SummitReader.dms("-71:18:00", "lon"), 1e-12);
    }

    @Test
    void badLinesNameTheLineOrAreSkippedWhenLenient() {
        String text = "  7:25:12 45:08:25  1325  R0 E07 BA MONTE CURT\n  7:25:12 45:61:25  1325  R0 E07 BA BAD MINUTES\n"
                + "  7:25:12 45:08:25  high  R0 E07 BA BAD HEIGHT\n  7:25:12\n";
        SummitFormatException e = assertThrows(SummitFormatException.class, () -> SummitReader.ferranti("alps.txt", text, false));
        assertTrue(e.getMessage().contains("alps.txt: line 2"), e.getMessage());
        SummitList l = SummitReader.ferranti("alps.txt", text, true);
        assertEquals(1, l.size());
        assertEquals(3, l.skipped().size());
        assertTrue(l.skipped().get(1).startsWith("line 3: bad elevation 'high'"), l.skipped().toString());
        assertTrue(l.skipped().get(2).startsWith("line 4:"), l.skipped().toString());
    }

    @Test
    void csvWithHeaderQuotesAndMissingElevation() {
        SummitList l = SummitReader.csv("c", "name,lat,lon,elevation\n\"Piz \"\"Bernina\"\", main\",46.3822,9.9078,4049\n"
                + "Nameless knob,46.1,9.1,\n", false);
        assertEquals(2, l.size());
        assertEquals("Piz \"Bernina\", main", l.summits().get(0).name());
        assertEquals(9.9078, l.summits().get(0).lonDeg());
        assertTrue(Double.isNaN(l.summits().get(1).elevationMetres()));
        SummitFormatException e = assertThrows(SummitFormatException.class,
                () -> SummitReader.csv("c.csv", "A,46,9,100\nB,95,9,100\n", false));
        assertTrue(e.getMessage().contains("line 2") && e.getMessage().contains("out of range"), e.getMessage());
    }

    @Test
    void geoJsonPointsWithEleUnits(@TempDir Path dir) throws Exception {
        Path f = dir.resolve("peaks.geojson");
        Files.writeString(f, """
                {"type": "FeatureCollection", "features": [
                  {"type": "Feature", "geometry": {"type": "Point", "coordinates": [8.0942, 46.4314]},
                   "properties": {"natural": "peak", "name": "Eggishorn", "ele": "2926.6 m"}},
                  {"type": "Feature", "geometry": {"type": "LineString", "coordinates": [[8, 46], [8.1, 46.1]]},
                   "properties": {"name": "a ridge"}}
                ]}""");
        SummitFormatException e = assertThrows(SummitFormatException.class, () -> SummitReader.read(f, false));
        assertTrue(e.getMessage().contains("line 2") && e.getMessage().contains("not a Point"), e.getMessage());
        SummitList l = SummitReader.read(f, true);
        assertEquals(1, l.size());
        assertEquals(2926.6, l.summits().get(0).elevationMetres(), 1e-9);
        assertEquals(46.4314, l.summits().get(0).latDeg());
        Path bad = dir.resolve("x.geojson");
        Files.writeString(bad, "{not json");
        assertThrows(SummitFormatException.class, () -> SummitReader.read(bad, true));
    }

    @Test
    void theSharedAlpineListReadsStrictly() throws Exception {
        Path alps = SharedData.require("peaks/alps.txt");
        SummitList l = SummitReader.read(alps, false);
        assertEquals(21069, l.size());
        Summit finsteraarhorn = l.summits().stream().filter(s -> s.name().equals("FINSTERAARHORN")).findFirst().orElseThrow();
        assertEquals(4274, finsteraarhorn.elevationMetres());
        assertEquals(46.5372, finsteraarhorn.latDeg(), 1e-3);
    }
}

package dempano.summits;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.SharedData;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

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
    void summitsWithoutAnElevationAreSaidToBeLeftOut() {
        // Projection places a summit by its height: one without is left out, which was silent.
        SummitList l = SummitReader.csv("p.csv", "name,lat,lon,ele\nNoHeight,46.55,8.55,\nOK,46.56,8.55,2400\n", false);
        assertEquals(2, l.size());
        assertEquals(List.of("1 of the 2 summits in p.csv have no elevation (e.g. NoHeight): each is placed at the DEM's"
                + " height at its position, a little low where the DEM flattens a summit"), l.warnings());
    }

    @Test
    void aGeoJsonNameWithLineBreaksIsOneLine(@TempDir Path dir) throws Exception {
        // It became two broken rows of P-summits.csv.
        Path f = Files.writeString(dir.resolve("p.geojson"), "{\"type\": \"FeatureCollection\", \"features\": [{\"type\":"
                + " \"Feature\", \"geometry\": {\"type\": \"Point\", \"coordinates\": [8.56, 46.56]}, \"properties\":"
                + " {\"name\": \"CR\\rLF\\nTab\\tEnd\", \"ele\": 2400}}]}");
        SummitList l = SummitReader.read(f, false);
        assertEquals("CR LF Tab End", l.summits().get(0).name());
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
        assertTrue(e.getMessage().contains("feature 2: geometry is not a Point"), e.getMessage());
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

    /** Header spellings and column orders; each row is written in the header's order from known values. */
    static Stream<Arguments> csvHeaders() {
        return Stream.of(
                Arguments.of("name,lat,lon,elevation"),
                Arguments.of("name,latitude,longitude,elevation"),
                Arguments.of("Name,Latitude,Longitude,Ele"),
                Arguments.of("NAME,LAT,LNG,HEIGHT"),
                Arguments.of("name,lat,long,elev"),
                Arguments.of("ele,lon,name,lat"),
                Arguments.of("id, latitude , name ,longitude,altitude,prominence"),
                Arguments.of("lat,lon,name,alt"));
    }

    @ParameterizedTest
    @MethodSource("csvHeaders")
    void csvHeaderNamesTheColumnsInAnyOrder(String header) {
        String[][] summits = {{"Piz Bernina", "46.3822", "9.9078", "4049"}, {"Eggishorn", "46.4314", "8.0942", "2926.6"}};
        StringBuilder text = new StringBuilder(header).append('\n');
        for (String[] s : summits) {
            List<String> row = new ArrayList<>();
            for (String column : header.split(",")) {
                row.add(switch (column.strip().toLowerCase(Locale.ROOT)) {
                    case "name" -> s[0];
                    case "lat", "latitude" -> s[1];
                    case "lon", "lng", "long", "longitude" -> s[2];
                    case "ele", "elevation", "elev", "height", "alt", "altitude" -> s[3];
                    default -> "17"; // a column the reader must ignore
                });
            }
            text.append(String.join(",", row)).append('\n');
        }
        SummitList l = SummitReader.csv("h.csv", text.toString(), false);
        assertEquals(2, l.size(), header);
        for (int i = 0; i < summits.length; i++) {
            Summit got = l.summits().get(i);
            assertEquals(summits[i][0], got.name(), header);
            assertEquals(Double.parseDouble(summits[i][1]), got.latDeg(), header);
            assertEquals(Double.parseDouble(summits[i][2]), got.lonDeg(), header);
            assertEquals(Double.parseDouble(summits[i][3]), got.elevationMetres(), header);
        }
        assertEquals(List.of(), l.warnings());
    }

    @Test
    void csvHeadlessAndHeaderProblems() {
        SummitList headerless = SummitReader.csv("c.csv", "Piz Bernina,46.3822,9.9078,4049\n", false);
        assertEquals(new Summit("Piz Bernina", 46.3822, 9.9078, 4049), headerless.summits().get(0));
        SummitList noEle = SummitReader.csv("c.csv", "name,lat,lon\nKnob,46.1,9.1\n", false);
        assertTrue(Double.isNaN(noEle.summits().get(0).elevationMetres()));
        SummitFormatException e = assertThrows(SummitFormatException.class,
                () -> SummitReader.csv("c.csv", "# list\nname,elevation,lon\nA,100,9\n", true));
        assertTrue(e.getMessage().startsWith("c.csv: line 2:") && e.getMessage().contains("no latitude column"), e.getMessage());
        e = assertThrows(SummitFormatException.class, () -> SummitReader.csv("c.csv", "name,lat,latitude,lon\n", true));
        assertTrue(e.getMessage().contains("two latitude columns"), e.getMessage());
        e = assertThrows(SummitFormatException.class, () -> SummitReader.csv("c.csv", "peak,y,x,z\nA,46,9,100\n", false));
        assertTrue(e.getMessage().contains("line 1") && e.getMessage().contains("names no known column"), e.getMessage());
        e = assertThrows(SummitFormatException.class, () -> SummitReader.csv("c.csv", "name,lat,lon,ele\nA,46,9\n", false));
        assertTrue(e.getMessage().contains("line 2: expected 4 fields as in the header, got 3"), e.getMessage());
    }

    @Test
    void csvQuotingProblemsNameTheLineAndLineBreaksInQuotesKeepTheCount() {
        SummitList l = SummitReader.csv("q.csv", "\"Two\nline name\",46,9,100\n\n\"X\",95,9,100\n", true);
        assertEquals("Two line name", l.summits().get(0).name());
        assertEquals(List.of("line 4: latitude 95.0 out of range -90…90"), l.skipped());
        SummitFormatException e = assertThrows(SummitFormatException.class,
                () -> SummitReader.csv("q.csv", "A,46,9,100\n\"B,46,9,100\nC,46,9,100\n", true));
        assertTrue(e.getMessage().startsWith("q.csv: line 2: a quoted field is not closed"), e.getMessage());
        e = assertThrows(SummitFormatException.class,
                () -> SummitReader.csv("q.csv", "A,46,9,100\n# note\n\"B\"x,46,9,100\n", true));
        assertTrue(e.getMessage().startsWith("q.csv: line 3: text after a closing quote"), e.getMessage());
        assertFalse(e.getMessage().contains("Exception"), e.getMessage());
    }

    /** The same two summits and a bad third line, with each line ending, in both text formats. */
    @ParameterizedTest
    @ValueSource(strings = {"\n", "\r\n", "\r"})
    void everyLineEndingSplitsLines(String eol) {
        String txt = String.join(eol, "# de Ferranti", "  7:25:12 45:08:25  1325  R0 E07 BA MONTE CURT",
                "  8:05:39 46:25:53  2927  H1 B02 G5 EGGISHORN", "", "  8:05:39 46:25:53  high  H1 B02 G5 BAD", "");
        String csv = String.join(eol, "# list", "name,lat,lon,ele", "MONTE CURT,45.14,7.42,1325", "",
                "EGGISHORN,46.4314,8.0942,2927", "BAD,46,8,high");
        for (boolean isCsv : new boolean[] {false, true}) {
            String text = isCsv ? csv : txt;
            SummitList l = isCsv ? SummitReader.csv("l.csv", text, true) : SummitReader.ferranti("l.txt", text, true);
            assertEquals(List.of("MONTE CURT", "EGGISHORN"), l.summits().stream().map(Summit::name).toList());
            assertEquals(1, l.skipped().size(), l.skipped().toString());
            int badLine = isCsv ? 6 : 5;
            assertTrue(l.skipped().get(0).startsWith("line " + badLine + ": bad elevation 'high'"), l.skipped().toString());
            SummitFormatException e = assertThrows(SummitFormatException.class,
                    () -> {
                        if (isCsv) {
                            SummitReader.csv("l.csv", text, false);
                        } else {
                            SummitReader.ferranti("l.txt", text, false);
                        }
                    });
            assertTrue(e.getMessage().contains("line " + badLine + ":"), e.getMessage());
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"0x2Bp0", "43.8f", "43.8F", "100D", "46d", "NaN", "Infinity", "-Infinity", "4_6", "46,5", "1e999", " ", "+-4"})
    void onlyPlainDecimalsAreNumbers(String bad) {
        SummitFormatException e = assertThrows(SummitFormatException.class,
                () -> SummitReader.csv("n.csv", "A,\"" + bad + "\",9,100\n", false), bad);
        assertTrue(e.getMessage().contains("line 1: bad latitude"), e.getMessage());
        e = assertThrows(SummitFormatException.class,
                () -> SummitReader.ferranti("n.txt", "  7:25:12 45:08:25  " + bad.strip() + "x  R0 E07 BA X\n", false));
        assertTrue(e.getMessage().contains("bad elevation"), e.getMessage());
    }

    @ParameterizedTest
    @ValueSource(strings = {"46", "+46.5", "-46.5", ".5", "46.", "4.65e1", "465E-1", "-0"})
    void plainDecimalsReadAsJavaReadsThem(String good) {
        SummitList l = SummitReader.csv("n.csv", "A," + good + ",9,100\n", false);
        assertEquals(Double.parseDouble(good), l.summits().get(0).latDeg(), good);
    }

    @Test
    void coordinatesOutsideTheGlobeAreBadLines() {
        SummitList l = SummitReader.csv("r.csv", "A,90,180,1\nB,-90,-180,1\nC,90.0001,0,1\nD,0,-180.5,1\n", true);
        assertEquals(2, l.size());
        assertEquals(List.of("line 3: latitude 90.0001 out of range -90…90", "line 4: longitude -180.5 out of range -180…180"),
                l.skipped());
    }

    @ParameterizedTest
    @ValueSource(strings = {"", "\n\n", "# nothing here\n", "name,lat,lon,elevation\n", "name,lat,lon,elevation\r# x\r"})
    void anEmptyListIsReportedAsAWarning(String text) {
        SummitList l = SummitReader.csv("empty.csv", text, false);
        assertEquals(0, l.size());
        assertEquals(List.of("no summits in empty.csv"), l.warnings());
        assertEquals(List.of("no summits in empty.txt"), SummitReader.ferranti("empty.txt", text.replace("name,", "#"), false).warnings());
    }

    @Test
    void anAllBadListSaysSoInItsWarning(@TempDir Path dir) throws Exception {
        Path f = dir.resolve("bad.csv");
        Files.writeString(f, "A,95,9,100\nB,46,9,x\n");
        SummitList l = SummitReader.read(f, true);
        assertEquals(List.of("no summits in " + f + " (all 2 entries were skipped as bad)"), l.warnings());
        Path g = dir.resolve("none.geojson");
        Files.writeString(g, "{\"type\": \"FeatureCollection\", \"features\": []}");
        assertEquals(List.of("no summits in " + g), SummitReader.read(g, false).warnings());
    }

    @Test
    void geoJsonProblemsInPlainWordsByFeature(@TempDir Path dir) throws Exception {
        String point = "{\"type\": \"Feature\", \"geometry\": {\"type\": \"Point\", \"coordinates\": %s}, \"properties\": %s}";
        List<String> features = List.of(
                String.format(point, "[8.0942, 46.4314]", "{\"name\": \"Eggishorn\", \"ele\": 2926.6}"),
                "42",
                "{\"type\": \"Feature\", \"properties\": {\"name\": \"no geometry\"}}",
                String.format(point, "[\"8.1\", \"46.1\"]", "{\"name\": \"string coordinates\"}"),
                String.format(point, "[8.1]", "{\"name\": \"one coordinate\"}"),
                String.format(point, "[8.1, 46.1]", "{\"name\": {\"en\": \"object\"}}"),
                String.format(point, "[8.1, 46.1]", "{\"name\": \"Hex\", \"ele\": \"0x2B\"}"),
                String.format(point, "[8.1, 96.1]", "{\"name\": \"Beyond the pole\"}"),
                String.format(point, "[8.1, 46.1]", "{\"name\": \"Bettmerhorn\", \"ele\": \"2857 m\"}"));
        Path f = dir.resolve("peaks.geojson");
        Files.writeString(f, "{\"type\": \"FeatureCollection\", \"features\": [\n" + String.join(",\n", features) + "]}");
        SummitList l = SummitReader.read(f, true);
        assertEquals(List.of("Eggishorn", "Bettmerhorn"), l.summits().stream().map(Summit::name).toList());
        assertEquals(2857, l.summits().get(1).elevationMetres());
        assertEquals(List.of(
                "feature 2: not a GeoJSON Feature (not an object)",
                "feature 3: geometry is not a Point",
                "feature 4: no numeric coordinates (want [longitude, latitude])",
                "feature 5: no numeric coordinates (want [longitude, latitude])",
                "feature 6: no name property",
                "feature 7: bad ele '0x2B' (want metres as a decimal number)",
                "feature 8: latitude 96.1 out of range -90…90"), l.skipped());
        SummitFormatException e = assertThrows(SummitFormatException.class, () -> SummitReader.read(f, false));
        assertEquals(f + ": feature 2: not a GeoJSON Feature (not an object) (read leniently to skip bad features)", e.getMessage());
    }

    @ParameterizedTest
    @ValueSource(strings = {"{not json", "[1, 2]", "{\"features\": 3}", "{\"features\": [NaN]}", "{\"features\": []} trailing",
            "{'features': []}"})
    void unreadableGeoJsonIsOneMessageWithoutInternals(String text, @TempDir Path dir) throws Exception {
        Path f = dir.resolve("x.geojson");
        Files.writeString(f, text);
        SummitFormatException e = assertThrows(SummitFormatException.class, () -> SummitReader.read(f, true));
        String m = e.getMessage();
        assertTrue(m.startsWith(f + ": not "), m);
        for (String internal : List.of("gson", "Exception", "Json", "$", "http", "\n")) {
            assertFalse(m.contains(internal), m);
        }
    }
}

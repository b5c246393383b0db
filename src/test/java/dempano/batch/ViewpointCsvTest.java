package dempano.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.PanoramaRequest;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The viewpoint file: rows with their values or one-line reasons, and files that cannot be used at all. */
class ViewpointCsvTest {
    static final PanoramaRequest DEFAULTS = PanoramaRequest.at(0, 0).withRangeMetres(50_000).withPixelsPerDegree(10)
            .withEyeHeightMetres(3).withOffsetMetres(1.5);

    static ViewpointCsv.Parsed parse(String text) throws ViewpointCsvException {
        return ViewpointCsv.parse("v.csv", text, DEFAULTS);
    }

    /**
     * One data line under the header {@code id,lat,lon,altitude_m,offset_m,eye_height_m,range_km,ppd}:
     * either valid (message "-") or invalid with the reason's start (after "line 2: ").
     */
    @ParameterizedTest(name = "[{index}] {0} → {1}")
    @CsvSource(delimiter = '|', quoteCharacter = '`', value = {
            // data line                                  | reason (or - for a valid row)
            "a,46.5,8.1,,,,,                              | -",
            "a,-90,-180,,,,,                              | -",
            "a,+1.5e1,.5,,,,,                             | -",
            "a,NaN,8,,,,,                                 | latitude 'NaN' is not a decimal number",
            "a,46,Infinity,,,,,                           | longitude 'Infinity' is not a decimal number",
            "a,91,8,,,,,                                  | latitude must be in [-90, 90] degrees, got 91.0",
            "a,46,180.5,,,,,                              | longitude must be in",
            "a,1e999,8,,,,,                               | latitude '1e999' is out of range",
            "a,0x10,8,,,,,                                | latitude '0x10' is not a decimal number",
            "a,46.5d,8,,,,,                               | latitude '46.5d' is not a decimal number",
            "a,\"46,5\",8,,,,,                            | latitude '46,5' is not a decimal number",
            "a,46 N,8,,,,,                                | latitude '46 N' is not a decimal number",
            "a,,8,,,,,                                    | latitude is empty",
            "a,46,8,abc,,,,                               | altitude 'abc' is not a decimal number",
            "a,46,8,,12m,,,                               | offset '12m' is not a decimal number",
            "a,46,8,2000,5,,,                             | altitude_m and offset_m both set the standing height",
            "a,46,8,2000,,,,                              | -",
            "a,46,8,,5,,,                                 | -",
            "a,46,8,,,-1,,                                | eye height must be a number of metres in [0, 1e6)",
            "a,46,8,,,,0.01,                              | range must be between 0.1 and",
            "a,46,8,,,,,0                                 | pixels per degree",
            "a,46,8,,,,,1000                              | pixels per degree",
            "a,46,8,,,,                                   | 7 fields, the header has 8",
            "a,46,8,,,,,,                                 | 9 fields, the header has 8",
            "../x,46,8,,,,,                               | unsafe id '../x'",
            "a/b,46,8,,,,,                                | unsafe id 'a/b'",
            ".hidden,46,8,,,,,                            | unsafe id '.hidden'",
            "..,46,8,,,,,                                 | unsafe id '..'",
            "a.,46,8,,,,,                                 | unsafe id 'a.'",
            "\"a b\",46,8,,,,,                            | unsafe id 'a b'",
            "\"a\tb\",46,8,,,,,                           | unsafe id 'a?b'",
            "Zürich,46,8,,,,,                             | unsafe id 'Zürich'",
            ",46,8,,,,,                                   | the id is empty",
    })
    void oneRow(String line, String reason) throws ViewpointCsvException {
        List<BatchRow> rows = parse("id,lat,lon,altitude_m,offset_m,eye_height_m,range_km,ppd\n" + line + "\n").rows();
        assertEquals(1, rows.size());
        BatchRow r = rows.get(0);
        assertEquals(2, r.lineNumber());
        if (reason.equals("-")) {
            assertTrue(r.valid(), () -> "expected valid, got: " + r.error());
        } else {
            assertFalse(r.valid(), "expected an error starting with: " + reason);
            assertTrue(r.error().startsWith("line 2: " + reason), () -> "got: " + r.error());
            assertFalse(r.error().contains("\n"), "one line");
        }
    }

    @Test
    void aPhotoRowsSearchRangesAreReadAndABadOneIsThatRowsError() throws ViewpointCsvException {
        List<BatchRow> rows = parse("id,image,heading_deg,heading_range_deg,hfov_min_deg,hfov_max_deg,focal35_min_mm,"
                + "focal35_max_mm\n"
                + "compass,a.jpg,120,20,,,,\n"
                + "zoom,b.jpg,,,,,24,70\n"
                + "fov,c.jpg,,,40,60,,\n"
                + "none,d.jpg,,,,,,\n"
                + "half,e.jpg,,,40,,,\n"
                + "both,f.jpg,,,40,60,24,70\n"
                + "wide,g.jpg,,181,,,,\n").rows();
        assertEquals(20, rows.get(0).photo().ranges().headingRangeDeg());
        assertEquals(120, rows.get(0).photo().overrides().headingDeg());
        double[] zoom = rows.get(1).photo().ranges().hfovRangeDeg(6000, 4000);
        assertEquals(Math.toDegrees(2 * Math.atan(18 / 70.0)), zoom[0], 1e-9);
        assertEquals(Math.toDegrees(2 * Math.atan(18 / 24.0)), zoom[1], 1e-9);
        assertEquals(40, rows.get(2).photo().ranges().hfovMinDeg());
        assertEquals(60, rows.get(2).photo().ranges().hfovMaxDeg());
        assertEquals(dempano.orient.SearchRanges.NONE, rows.get(3).photo().ranges());
        for (int i = 4; i < 7; i++) {
            BatchRow r = rows.get(i);
            assertFalse(r.valid(), r.id());
            assertTrue(r.error().startsWith("line " + (i + 2) + ": search ranges (heading_range_deg, hfov_min_deg/hfov_max_deg,"),
                    r.error());
        }
        assertTrue(rows.get(4).error().contains("--hfov-range-deg must be MIN,MAX"), rows.get(4).error());
        assertTrue(rows.get(5).error().contains("not both"), rows.get(5).error());
        assertTrue(rows.get(6).error().contains("--heading-range-deg must be in"), rows.get(6).error());
        // Angles beyond a turn are that row's error.
        List<BatchRow> angles = parse("id,image,heading_deg,pitch_deg,roll_deg\nh,a.jpg,1e300,,\np,b.jpg,,-91,\n"
                + "r,c.jpg,,,180.5\nok,d.jpg,-360,90,-180\n").rows();
        assertEquals("line 2: heading_deg must be within ±360 degrees, got 1.0E300", angles.get(0).error());
        assertEquals("line 3: pitch_deg must be within ±90 degrees, got -91.0", angles.get(1).error());
        assertEquals("line 4: roll_deg must be within ±180 degrees, got 180.5", angles.get(2).error());
        assertTrue(angles.get(3).valid(), angles.get(3).error());
        // Two lenses: the focal length was left unused without a word.
        List<BatchRow> lenses = parse("id,image,hfov_deg,focal35_mm\nboth,a.jpg,50,200\none,b.jpg,50,\n").rows();
        assertEquals("line 2: hfov_deg and focal35_mm both set the field of view: give one", lenses.get(0).error());
        assertTrue(lenses.get(1).valid(), lenses.get(1).error());
        // A viewpoint (no image) may not fill them.
        BatchRow panorama = parse("id,lat,lon,image,hfov_min_deg,hfov_max_deg\np,46,8,,40,60\n").rows().get(0);
        assertFalse(panorama.valid());
        assertTrue(panorama.error().contains("hfov_min_deg is for photo rows"), panorama.error());
    }

    @Test
    void aPhotoRowWithAnAltitudeAndAnOffsetIsAnError() throws ViewpointCsvException {
        List<BatchRow> rows = parse("id,lat,lon,altitude_m,offset_m,image,heading_deg\n"
                + "p,46.5,8.25,3000,5,a.jpg,10\n" + "q,46.5,8.25,3000,,a.jpg,10\n").rows();
        assertFalse(rows.get(0).valid());
        assertTrue(rows.get(0).error().startsWith("line 2: altitude_m and offset_m both set the standing height"),
                rows.get(0).error());
        assertTrue(rows.get(1).valid(), rows.get(1).error());
    }

    @Test
    void optionalColumnsOverrideTheDefaultsAndEmptyCellsKeepThem() throws ViewpointCsvException {
        List<BatchRow> rows = parse("id,lat,lon,altitude_m,offset_m,eye_height_m,range_km,ppd\n"
                + "full,46.5,8.25,3000,,10,20,4\n"
                + "empty,46.5,8.25,,,,,\n"
                + "offset,46.5,8.25,,-2,,,\n").rows(); // an altitude and an offset in one row: that row's error
        PanoramaRequest full = rows.get(0).request(), empty = rows.get(1).request();
        assertEquals(46.5, full.latDeg());
        assertEquals(8.25, full.lonDeg());
        assertEquals(3000, full.altitudeMetres());
        assertEquals(-2, rows.get(2).request().offsetMetres());
        assertEquals(10, full.eyeHeightMetres());
        assertEquals(20_000, full.rangeMetres());
        assertEquals(4, full.pixelsPerDegree());
        assertTrue(Double.isNaN(empty.altitudeMetres()));
        assertEquals(DEFAULTS.offsetMetres(), empty.offsetMetres());
        assertEquals(DEFAULTS.eyeHeightMetres(), empty.eyeHeightMetres());
        assertEquals(DEFAULTS.rangeMetres(), empty.rangeMetres());
        assertEquals(DEFAULTS.pixelsPerDegree(), empty.pixelsPerDegree());
        // Everything else is the defaults' own.
        assertEquals(DEFAULTS.withOffsetMetres(0), ViewpointCsv.atViewpoint(DEFAULTS, 0, 0).withOffsetMetres(0));
    }

    @Test
    void bomCrlfBlankLinesHeaderCaseAndColumnOrder() throws ViewpointCsvException {
        ViewpointCsv.Parsed p = parse("\uFEFF Lon , ID ,Name,LAT\r\n8.1,a,Alpha,46.1\r\n\r\n   \r\n8.2,b,\"Beta,\r\nsecond line\",46.2\r\n8.3,c,Gamma,46.3");
        assertEquals(List.of("Name"), p.ignoredColumns());
        assertEquals(3, p.rows().size());
        assertEquals(List.of("a", "b", "c"), p.rows().stream().map(BatchRow::id).toList());
        assertEquals(List.of(2, 5, 7), p.rows().stream().map(BatchRow::lineNumber).toList());
        assertEquals(46.3, p.rows().get(2).request().latDeg());
        assertEquals(8.2, p.rows().get(1).request().lonDeg());
        assertTrue(p.rows().stream().allMatch(BatchRow::valid));
    }

    @Test
    void duplicateIdsAreErrorsWithoutRegardToCaseAndTheFirstStays() throws ViewpointCsvException {
        List<BatchRow> rows = parse("id,lat,lon\na,1,1\nb,2,2\nA,3,3\na,4,4\n").rows();
        assertTrue(rows.get(0).valid());
        assertTrue(rows.get(1).valid());
        assertEquals("line 4: duplicate id 'A' (first on line 2)", rows.get(2).error());
        assertEquals("line 5: duplicate id 'a' (first on line 2)", rows.get(3).error());
    }

    @Test
    void anIdWhoseFilesWouldBeAnotherIdsIsAnError() throws ViewpointCsvException {
        // 'a-distance.png' is a's distance picture and a-distance's colour panorama: the later row is refused,
        // whichever comes first; 'a-1' writes no name of a's.
        List<BatchRow> rows = parse("id,lat,lon\na,1,1\na-distance,2,2\nb-summits,3,3\nb,4,4\na-1,5,5\n").rows();
        assertTrue(rows.get(0).valid() && rows.get(2).valid() && rows.get(4).valid());
        assertEquals("line 3: id 'a-distance' would write a-distance.png, a file of id 'a' (line 2): choose ids that are"
                + " not another id with a file suffix", rows.get(1).error());
        assertEquals("line 5: id 'b' would write b-summits.json, a file of id 'b-summits' (line 4): choose ids that are"
                + " not another id with a file suffix", rows.get(3).error());
    }

    @Test
    void aBadRowDoesNotAffectTheNext() throws ViewpointCsvException {
        List<BatchRow> rows = parse("id,lat,lon\nx,abc,1\ny,2,2\n").rows();
        assertFalse(rows.get(0).valid());
        assertTrue(rows.get(1).valid());
        assertNull(rows.get(1).error());
    }

    /** Files that cannot be used at all: one line naming the file and the problem. */
    @ParameterizedTest(name = "[{index}] {1}")
    @CsvSource(delimiter = '|', quoteCharacter = '`', value = {
            "                              | v.csv: empty: want a header line naming the columns id,lat,lon",
            "\uFEFF                        | v.csv: empty",
            "id,lat\\na,1                   | v.csv: line 1: the header has no column 'lon' (it has: id, lat; required: id, lat, lon; or id and image for photos)",
            "lat,lon\\n1,2                  | v.csv: line 1: the header has no column 'id'",
            "id,lat,lon,LAT\\na,1,2,3       | v.csv: line 1: the header names column 'lat' twice",
            "id,lat,lon\\na,1,2\\n\"b,3,4\\n  | v.csv: broken CSV after line 3 (startline 3: EOF reached before encapsulated token finished): the file cannot be read past it",
            "id;lat;lon\\na;1;2           | v.csv: line 1: the header has no column 'id' (it has: id;lat;lon; required: id, lat, lon; or id and image for photos): the columns seem separated by semicolons; separate them by commas",
    })
    void unusableFiles(String text, String message) {
        ViewpointCsvException e = assertThrows(ViewpointCsvException.class,
                () -> parse(text == null ? "" : text.replace("\\n", "\n")));
        assertTrue(e.getMessage().startsWith(message), () -> "got: " + e.getMessage());
        assertFalse(e.getMessage().contains("\n"), "one line");
    }

    @Test
    void unreadableAndNonUtf8Files(@TempDir Path dir) throws IOException {
        ViewpointCsvException missing = assertThrows(ViewpointCsvException.class,
                () -> ViewpointCsv.read(dir.resolve("nope.csv"), DEFAULTS));
        assertTrue(missing.getMessage().startsWith("cannot read the viewpoint file " + dir.resolve("nope.csv")),
                missing.getMessage());
        // A row with bytes that are no UTF-8 is that row's error; the other rows go on. In the header: the file's.
        Path latin1 = Files.write(dir.resolve("latin1.csv"), "id,lat,lon\nZ\u00fcrich,47,8\nbern,46.9,7.4\n"
                .getBytes(StandardCharsets.ISO_8859_1));
        List<BatchRow> rows = ViewpointCsv.read(latin1, DEFAULTS).rows();
        assertEquals(2, rows.size());
        assertEquals("line 2: not UTF-8 text (bytes no UTF-8 character is made of; save the file as UTF-8)", rows.get(0).error());
        assertTrue(rows.get(1).valid(), rows.get(1).error());
        Path badHeader = Files.write(dir.resolve("header.csv"), "id,lat,lon\u00b0\na,47,8\n".getBytes(StandardCharsets.ISO_8859_1));
        ViewpointCsvException notUtf8 = assertThrows(ViewpointCsvException.class, () -> ViewpointCsv.read(badHeader, DEFAULTS));
        assertEquals(badHeader + ": line 1: not UTF-8 text (save the file as UTF-8)", notUtf8.getMessage());
        Path folder = Files.createDirectory(dir.resolve("folder.csv"));
        assertThrows(ViewpointCsvException.class, () -> ViewpointCsv.read(folder, DEFAULTS));
        Path ok = Files.writeString(dir.resolve("ok.csv"), "id,lat,lon\na,47,8\n");
        assertEquals(1, ViewpointCsv.read(ok, DEFAULTS).validCount());
    }

    @Test
    void idRules() {
        for (String good : List.of("a", "A1", "0", "summit_01", "x-y.z", "a".repeat(BatchIds.MAX_LENGTH))) {
            assertNull(BatchIds.problem(good), good);
        }
        for (String bad : List.of("", "..", ".", "./a", "a/b", "a\\b", "-a", "_a", "a b", "a.", "a".repeat(101), "a\u0000b", "é")) {
            assertTrue(BatchIds.problem(bad) != null, () -> "accepted: " + bad);
        }
        assertEquals(BatchIds.collisionKey("Abc"), BatchIds.collisionKey("aBC"));
    }

    @Test
    void commentLinesAreSkippedAndLaterRowsKeepTheirLineNumbers() throws ViewpointCsvException {
        // A "# note,44.27,…" line was a row with an unsafe id, and the batch's exit code said rows failed.
        List<BatchRow> rows = parse("# viewpoints for the survey\nid,lat,lon\n# the summit\na,46,8\n#b,46.1,8\nc,x,8\n").rows();
        assertEquals(2, rows.size());
        assertEquals("a", rows.get(0).id());
        assertTrue(rows.get(0).valid());
        assertEquals(6, rows.get(1).lineNumber());
        assertTrue(rows.get(1).error().startsWith("line 6: "), rows.get(1).error());
    }

    @Test
    void aDashReadsStandardInput() throws Exception {
        java.io.InputStream in = System.in;
        try {
            System.setIn(new java.io.ByteArrayInputStream("id,lat,lon\na,46,8\n".getBytes(StandardCharsets.UTF_8)));
            ViewpointCsv.Parsed p = ViewpointCsv.read(Path.of("-"), DEFAULTS);
            assertEquals(1, p.validCount());
        } finally {
            System.setIn(in);
        }
    }
}

package dempano.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.dem.DemoTerrain;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** {@code dempano batch} from the command line: exit codes, one line per problem, results.csv, same files as single runs. */
class BatchCommandTest {
    static final List<String> SMALL = List.of("--ppd", "4", "--range-km", "20", "--elevation-range", "-10:10");
    static Path demo;
    static double[] vp;

    @BeforeAll
    static void demoDem() throws IOException {
        demo = DemoTerrain.ensure(DemoTerrain.DEFAULT_DIR);
        vp = DemoTerrain.viewpoint();
    }

    static String[] batch(Path csv, Path out, String... more) {
        List<String> a = new ArrayList<>(List.of("batch", csv.toString(), "--out-dir", out.toString(), "--dem-dir", demo.toString()));
        for (int i = 0; i < SMALL.size(); i += 2) { // SMALL's settings unless given
            if (!List.of(more).contains(SMALL.get(i))) {
                a.addAll(SMALL.subList(i, i + 2));
            }
        }
        a.addAll(List.of(more));
        return MainTest.run(a.toArray(new String[0]));
    }

    static String coordinate(double v) {
        return String.format(Locale.ROOT, "%.6f", v);
    }

    /** The panorama options are declared once: dempano and dempano batch take the same ones, with the same defaults. */
    @Test
    void batchTakesEveryPanoramaOptionOfTheMainCommandWithItsDefault() {
        picocli.CommandLine.Model.CommandSpec main = new picocli.CommandLine(new Main()).getCommandSpec();
        picocli.CommandLine.Model.CommandSpec batch = new picocli.CommandLine(new BatchCommand()).getCommandSpec();
        picocli.CommandLine.Model.CommandSpec shared = new picocli.CommandLine(new PanoramaOptions()).getCommandSpec();
        assertTrue(shared.options().size() >= 19, "panorama options: " + shared.options().size());
        for (picocli.CommandLine.Model.OptionSpec o : shared.options()) {
            for (picocli.CommandLine.Model.CommandSpec spec : List.of(main, batch)) {
                picocli.CommandLine.Model.OptionSpec there = spec.findOption(o.longestName());
                assertTrue(there != null, spec.name() + " lacks " + o.longestName());
                assertEquals(o.defaultValue(), there.defaultValue(), o.longestName() + " default in " + spec.name());
            }
        }
        // A bad value is the same bad argument in both (exit 2), named in the message.
        assertEquals(2, Main.run("--void-fill", "kriging"));
        assertEquals(2, Main.run("batch", "x.csv", "--out-dir", "o", "--dem-dir", "d", "--void-fill", "kriging"));
        assertEquals(2, Main.run("--dem-blend", "feather"));
        assertEquals(2, Main.run("batch", "x.csv", "--out-dir", "o", "--dem-dir", "d", "--dem-blend", "feather"));
    }

    /**
     * The render options that apply to camera views are declared once too: {@code dempano photo} takes every one of
     * them with the main command's default, refuses the panorama-only ones, and passes them into the request.
     */
    @Test
    void photoTakesEveryRenderOptionOfTheMainCommandWithItsDefault() {
        picocli.CommandLine.Model.CommandSpec main = new picocli.CommandLine(new Main()).getCommandSpec();
        picocli.CommandLine.Model.CommandSpec photo = new picocli.CommandLine(new PhotoCommand()).getCommandSpec();
        picocli.CommandLine.Model.CommandSpec shared = new picocli.CommandLine(new RenderOptions()).getCommandSpec();
        assertTrue(shared.options().size() >= 11, "render options: " + shared.options().size());
        for (picocli.CommandLine.Model.OptionSpec o : shared.options()) {
            picocli.CommandLine.Model.OptionSpec inMain = main.findOption(o.longestName());
            picocli.CommandLine.Model.OptionSpec inPhoto = photo.findOption(o.longestName());
            assertTrue(inMain != null, "dempano lacks " + o.longestName());
            assertTrue(inPhoto != null, "dempano photo lacks " + o.longestName());
            assertEquals(inMain.defaultValue(), inPhoto.defaultValue(), o.longestName() + " default");
            assertEquals(inMain.description()[0], inPhoto.description()[0], o.longestName() + " description");
        }
        // Panorama-only options are not the photo's: its view is the photo's own grid, its eye the photo's pose.
        for (String panoramaOnly : List.of("--ppd", "--elevation-range", "--views", "--pfm")) {
            assertTrue(photo.findOption(panoramaOnly) == null, "photo takes " + panoramaOnly);
        }
        // --offset-m and --eye-height-m stay the photo's own: unset unless given (EXIF or DEM otherwise).
        assertEquals(null, photo.findOption("--offset-m").defaultValue());
        // The values reach the request a photo is rendered with.
        PhotoCommand cmd = new PhotoCommand();
        new picocli.CommandLine(cmd).parseArgs("--dem-dir", "d", "--layers", "elevation,incidence", "--renderer", "reference",
                "--range-km", "35", "--refraction", "0", "--supersampling", "2", "--no-exact-distances", "--near-m", "3");
        dempano.PanoramaRequest r = cmd.render.applyTo(dempano.PanoramaRequest.at(0, 0), dempano.PanoramaRequest.DEFAULT_RANGE_METRES);
        assertEquals(java.util.EnumSet.of(dempano.panorama.Layer.ELEVATION, dempano.panorama.Layer.INCIDENCE), r.layers());
        assertEquals(35_000, r.rangeMetres(), 1e-9);
        assertEquals(0, r.refraction().coefficient(), 0);
        assertEquals(2, r.supersampling(), 0);
        assertEquals(3, r.nearMetres(), 0);
        assertFalse(r.exactDistances());
        assertTrue(cmd.render.referenceRenderer());
        // The defaults are those the photo command had before (100 km, k 0.13, supersampling 1, exact on).
        PhotoCommand plain = new PhotoCommand();
        new picocli.CommandLine(plain).parseArgs("--dem-dir", "d");
        dempano.PanoramaRequest d = plain.render.applyTo(dempano.PanoramaRequest.at(0, 0), dempano.PanoramaRequest.DEFAULT_RANGE_METRES);
        assertEquals(100_000, d.rangeMetres(), 0);
        assertEquals(0.13, d.refraction().coefficient(), 0);
        assertEquals(1, d.supersampling(), 0);
        assertTrue(d.exactDistances());
        // A bad value is a bad argument (exit 2), as in the other commands; so is a panorama-only option.
        assertEquals(2, Main.run("photo", "--dem-dir", "d", "--void-fill", "kriging"));
        assertEquals(2, Main.run("photo", "--dem-dir", "d", "--dem-blend", "feather"));
        // The DEM fill reaches the DEM: the best measured by default, the one asked for otherwise.
        assertEquals(dempano.dem.DemFill.DEFAULT, plain.render.demFill());
        PhotoCommand asIs = new PhotoCommand();
        new picocli.CommandLine(asIs).parseArgs("--dem-dir", "d", "--dem-blend", "as-is", "--void-fill", "idw");
        assertEquals(new dempano.dem.DemFill(dempano.dem.VoidFill.IDW, dempano.dem.PriorityDem.Blend.AS_IS), asIs.render.demFill());
        assertEquals(2, Main.run("photo", "--dem-dir", "d", "--ppd", "30"));
    }

    @Test
    void oneBadRowIsReportedInOneLineTheRestAreDoneAndEqualSingleRuns(@TempDir Path d) throws IOException {
        String lat = coordinate(vp[0]), lon = coordinate(vp[1]);
        Path csv = Files.writeString(d.resolve("v.csv"), "id,lat,lon,eye_height_m,note\n"
                + "here," + lat + "," + lon + ",,start\n"
                + "bad," + lat + ",abc,,typo\n"
                + "north," + coordinate(vp[0] + 0.04) + "," + lon + ",20,\n"
                + "south," + coordinate(vp[0] - 0.04) + "," + lon + ",,\n");
        Path out = d.resolve("out/new"); // created
        String[] r = batch(csv, out);
        assertEquals("3", r[0], r[1]);
        List<String> errorLines = r[1].lines().filter(l -> l.contains(" error: ")).toList();
        assertEquals(List.of("dempano batch: [2/4] bad error: line 3: longitude 'abc' is not a decimal number"), errorLines);
        assertFalse(r[1].contains("Exception"), r[1]);
        assertTrue(r[1].contains("ignoring columns note"), r[1]);
        assertTrue(r[1].contains("3 ok, 1 failed, 0 not run of 4 rows"), r[1]);
        List<String> results = Files.readAllLines(out.resolve("results.csv"));
        assertEquals("id,status,files,seconds,error", results.get(0));
        assertTrue(results.get(1).startsWith("here,ok,here.png here-distance.npy here-distance.png here.json,"), results.get(1));
        assertEquals("bad,error,,0.000,line 3: longitude 'abc' is not a decimal number", results.get(2));
        assertTrue(results.get(3).startsWith("north,ok,"), results.get(3));
        assertTrue(results.get(4).startsWith("south,ok,"), results.get(4));
        assertEquals(5, results.size());
        com.google.gson.JsonObject json = com.google.gson.JsonParser.parseString(Files.readString(out.resolve("here.json")))
                .getAsJsonObject();
        assertEquals(dempano.terrain.LevelOfDetail.DEFAULT_MAX_ERROR_PX, json.get("lodErrorPx").getAsDouble(), 0);
        assertTrue(json.get("terrainTriangles").getAsLong() > 0, json.toString());

        // The same viewpoint rendered by the single-panorama command: the same distance file, byte for byte.
        List<String> single = new ArrayList<>(List.of("--lat", coordinate(vp[0] + 0.04), "--lon", lon, "--eye-height-m", "20",
                "--dem-dir", demo.toString(), "--out", d.resolve("single").toString()));
        single.addAll(SMALL);
        String[] s = MainTest.run(single.toArray(new String[0]));
        assertEquals("0", s[0], s[1]);
        assertArrayEquals(Files.readAllBytes(d.resolve("single-distance.npy")), Files.readAllBytes(out.resolve("north-distance.npy")));
    }

    @Test
    void allRowsDoneIsExitZeroAndProgressShowsRateAndEta(@TempDir Path d) throws IOException {
        Path csv = Files.writeString(d.resolve("v.csv"), "id,lat,lon\na," + coordinate(vp[0]) + "," + coordinate(vp[1])
                + "\nb," + coordinate(vp[0] + 0.01) + "," + coordinate(vp[1]) + "\n");
        String[] r = batch(csv, d, "--renderer", "reference", "--ppd", "2", "--progress");
        assertEquals("0", r[0], r[1]);
        assertTrue(r[1].contains("2/2 pano"), r[1]);
        assertTrue(r[1].contains("pano/s"), r[1]);
        assertTrue(Files.exists(d.resolve("b.json")));
        assertEquals(3, Files.readAllLines(d.resolve("results.csv")).size());
    }

    /** Unusable input: exit 1 (2 for bad arguments) and one line saying what is wrong, no stack trace, nothing rendered. */
    @ParameterizedTest(name = "[{index}] {2}")
    @CsvSource(delimiter = '|', value = {
            // CSV text (or - for no file) | exit | message
            "id,lat\\na,1                  | 1    | v.csv: line 1: the header has no column 'lon' (it has: id, lat; required: id, lat, lon; or id and image for photos)",
            "                               | 1    | v.csv: empty: want a header line naming the columns id,lat,lon",
            "-                              | 1    | cannot read the viewpoint file",
            "id,lat,lon\\na,\"1,2\\n       | 1    | v.csv: broken CSV after line 2",
    })
    void unusableViewpointFiles(String text, int exit, String message, @TempDir Path d) throws IOException {
        Path csv = d.resolve("v.csv");
        if (!"-".equals(text)) {
            Files.writeString(csv, text == null ? "" : text.replace("\\n", "\n"));
        }
        String[] r = batch(csv, d.resolve("out"));
        assertEquals(Integer.toString(exit), r[0], r[1]);
        List<String> lines = r[1].lines().toList();
        assertEquals(1, lines.size(), r[1]);
        assertTrue(lines.get(0).startsWith("dempano batch: ") && lines.get(0).contains(message), r[1]);
        assertFalse(Files.exists(d.resolve("out")), "nothing created");
    }

    @Test
    void aMissingDemFolderOrAnOutputFolderThatIsAFileIsExitOne(@TempDir Path d) throws IOException {
        Path csv = Files.writeString(d.resolve("v.csv"), "id,lat,lon\na,0.1,0.1\n");
        String[] r = MainTest.run("batch", csv.toString(), "--out-dir", d.resolve("out").toString(), "--dem-dir",
                d.resolve("no-such-dem").toString());
        assertEquals("1", r[0], r[1]);
        assertTrue(r[1].contains("no-such-dem"), r[1]);
        assertFalse(r[1].contains("\tat "), r[1]);
        assertFalse(Files.exists(d.resolve("out")), "nothing created");
        Path file = Files.writeString(d.resolve("file"), "x");
        r = batch(csv, file);
        assertEquals("1", r[0], r[1]);
        assertTrue(r[1].contains("dempano batch: cannot create the output folder " + file), r[1]);
    }

    @Test
    void aViewpointsFileTheBatchWouldWriteOverIsExitOneAndKept(@TempDir Path d) throws IOException {
        Path out = Files.createDirectories(d.resolve("out"));
        String text = "id,lat,lon\na,0.1,0.1\n";
        for (String name : new String[] {"results.csv", "a.json", "a-distance.png"}) {
            Path csv = Files.writeString(out.resolve(name), text);
            String[] r = batch(csv, out);
            assertEquals("1", r[0], r[1]);
            assertTrue(r[1].contains("dempano batch: cannot read and write " + csv + ": it is "), r[1]);
            assertEquals(text, Files.readString(csv), name);
            Files.delete(csv);
        }
    }

    @ParameterizedTest(name = "[{index}] {0}")
    @CsvSource(delimiter = '|', value = {
            "--ppd -3                 | pixels per degree",
            "--range-km 0             | range must be",
            "--missing-tiles maybe    | --missing-tiles must be auto, sea or error",
            "--renderer vulkan        | --renderer must be opengl or reference",
    })
    void badOptionsAreExitTwo(String option, String message, @TempDir Path d) throws IOException {
        Path csv = Files.writeString(d.resolve("v.csv"), "id,lat,lon\na,0.1,0.1\n");
        String[] r = batch(csv, d.resolve("out"), option.trim().split(" "));
        assertEquals("2", r[0], r[1]);
        assertTrue(r[1].contains(message), r[1]);
        assertFalse(r[1].contains("\tat "), r[1]);
    }

    @Test
    void missingArgumentsAreExitTwo(@TempDir Path d) {
        String[] r = MainTest.run("batch", d.resolve("v.csv").toString());
        assertEquals("2", r[0], r[1]);
        assertTrue(r[1].contains("--out-dir"), r[1]);
        assertTrue(Arrays.asList(r[1].split("\n")).size() <= 3, r[1]);
    }

    @Test
    void theProgressBarOpensNoTerminalOfItsOwn() throws Exception {
        // progressbar's own console consumer opened a JLine system terminal to learn the width, and JLine took over
        // SIGINT: Ctrl-C on a terminal killed the batch outright (no row finished, staging folders and unlisted sets
        // left; a hostile test on a pty). The bar asks stderr's width itself: the library's terminal stays unopened.
        java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
        java.io.PrintStream err = new java.io.PrintStream(bytes, true, java.nio.charset.StandardCharsets.UTF_8);
        BatchCommand.Bar bar = new BatchCommand.Bar(err, false);
        dempano.batch.BatchRow row = dempano.batch.BatchRow.of("p0", dempano.PanoramaRequest.at(46, 8));
        bar.started(2);
        bar.rowStarted(row, 0);
        bar.rowFinished(new dempano.batch.BatchResult("p0", 2, dempano.batch.BatchResult.Status.ERROR, List.of(), 0.1, "line 2: no data"), 0);
        bar.finished(null);
        // (The library closes its terminal again when a bar closes: its consumer is asked directly.)
        me.tongfei.progressbar.ConsoleProgressBarConsumer consumer = BatchCommand.Bar.consumer(err, true);
        assertTrue(consumer.getMaxRenderedLength() > 0);
        consumer.accept("batch 0% [ ] 0/2 pano");
        Class<?> utils = Class.forName("me.tongfei.progressbar.TerminalUtils");
        java.lang.reflect.Field terminal = utils.getDeclaredField("terminal");
        terminal.setAccessible(true);
        assertEquals(null, terminal.get(null), "the progress bar library opened a terminal");
        String out = bytes.toString(java.nio.charset.StandardCharsets.UTF_8);
        assertTrue(out.contains("batch") && out.contains("[1/2] p0 error: line 2: no data"), out);
        for (String line : out.split("[\r\n]")) {
            assertTrue(line.length() < StderrTerminal.DEFAULT_COLUMNS, "wider than the assumed terminal: " + line);
        }
    }

    @Test
    void aRowsLineShowsItsIdWithoutControlCharacters() {
        // An id with a newline or an escape (refused, but reported) printed raw: two lines, or a terminal's colours.
        dempano.batch.BatchRow row = dempano.batch.BatchRow.of("a\nb\u001b[31m", dempano.PanoramaRequest.at(46, 8));
        String line = BatchCommand.line(new dempano.batch.BatchResult(row.id(), 5, dempano.batch.BatchResult.Status.ERROR, List.of(), 0, "unsafe id"), 3, 9);
        assertEquals("dempano batch: [4/9] a?b?[31m error: unsafe id", line);
    }

    @Test
    void aViewpointFileThatIsTheResultsFileThroughALinkIsRefused(@TempDir Path dir) throws IOException {
        // Refused by name in the output folder, but a link to it from elsewhere ran, and the viewpoints were
        // overwritten by the results (a hostile test).
        Path out = Files.createDirectories(dir.resolve("out"));
        Path results = Files.writeString(out.resolve("results.csv"), "id,lat,lon\na,46,8\n");
        Path link = Files.createSymbolicLink(dir.resolve("link.csv"), results);
        List<dempano.batch.BatchRow> rows = List.of(dempano.batch.BatchRow.of("a", dempano.PanoramaRequest.at(46, 8)));
        assertEquals("the results file", BatchCommand.writtenOver(results, out, rows));
        assertEquals("the results file", BatchCommand.writtenOver(link, out, rows));
        Path aRowsOutput = Files.createSymbolicLink(dir.resolve("b.csv"), Files.writeString(out.resolve("a.json"), ""));
        assertEquals("an output of row 'a'", BatchCommand.writtenOver(aRowsOutput, out, rows));
        assertEquals(null, BatchCommand.writtenOver(Files.writeString(dir.resolve("v.csv"), ""), out, rows));
    }
}

package dempano.spark;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.cli.BatchCommand;
import dempano.dem.DemoTerrain;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVParser;
import org.apache.commons.csv.CSVRecord;
import org.apache.spark.sql.Row;
import org.apache.spark.sql.RowFactory;
import org.apache.spark.sql.SparkSession;
import org.apache.spark.sql.types.DataTypes;
import org.apache.spark.sql.types.StructType;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * The Spark job in local mode ({@code local[2]}: two executor threads sharing one renderer) on the
 * demo DEM, 20 rows (one bad), 4 px/°, 20 km: every row's files equal {@code dempano batch}'s bit for
 * bit (the JSON's timings aside), and the bad row is an error line in the results table.
 */
class SparkBatchTest {
    static SparkSession spark;
    @TempDir
    static Path tmp;

    @BeforeAll
    static void start() {
        spark = SparkSession.builder().master("local[2]").appName("dempano-spark-test")
                .config("spark.ui.enabled", "false").config("spark.sql.shuffle.partitions", "4")
                .config("spark.driver.host", "127.0.0.1").getOrCreate();
    }

    @AfterAll
    static void stop() {
        if (spark != null) {
            spark.stop();
        }
        ExecutorRenderer.closeAll();
    }

    static final String[] OPTIONS = {"--ppd", "4", "--range-km", "20", "--elevation-range", "-10:10"};

    /** 20 rows over the demo DEM's four tiles; row 13 has a latitude that is not a number. */
    static String viewpoints() {
        StringBuilder b = new StringBuilder("id,lat,lon,eye_height_m,note\n");
        int i = 0;
        for (double lat : new double[] {-0.55, -0.15, 0.25, 0.65}) {
            for (double lon : new double[] {-0.6, -0.3, 0.05, 0.35, 0.7}) {
                String latText = i == 13 ? "north" : String.format(Locale.ROOT, "%.3f", lat + 0.01 * i);
                b.append(String.format(Locale.ROOT, "p%02d,%s,%.3f,%s,\"a note, quoted\"%n", i, latText, lon,
                        i % 3 == 0 ? "30" : ""));
                i++;
            }
        }
        return b.toString();
    }

    @Test
    void localModeEqualsBatchModeBitForBitAndTheBadRowIsInTheResults() throws IOException {
        Path dem = DemoTerrain.ensure(tmp.resolve("dem"));
        Path csv = tmp.resolve("viewpoints.csv");
        Files.writeString(csv, viewpoints(), StandardCharsets.UTF_8);

        // Single-machine batch mode, as the CLI runs it.
        Path batchOut = tmp.resolve("batch");
        List<String> batchArgs = new ArrayList<>(List.of(csv.toString(), "--out-dir", batchOut.toString(), "--dem-dir", dem.toString()));
        batchArgs.addAll(List.of(OPTIONS));
        assertEquals(BatchCommand.EXIT_SOME_ROWS_FAILED, new CommandLine(new BatchCommand()).execute(batchArgs.toArray(new String[0])));

        // The Spark job, output through Hadoop's FileSystem API (a file: URI), rows ordered by tile over 3 tasks.
        Path sparkOut = tmp.resolve("spark");
        SparkBatchMain main = new SparkBatchMain();
        List<String> sparkArgs = new ArrayList<>(List.of(csv.toString(), "--out-dir", sparkOut.toUri().toString(), "--dem-dir", dem.toString()));
        sparkArgs.addAll(List.of(OPTIONS));
        new CommandLine(main).parseArgs(sparkArgs.toArray(new String[0]));
        SparkBatch.Summary s = SparkBatch.run(spark, SparkBatch.read(spark, csv.toString(), null), main.settings(),
                SparkBatch.Order.TILE, 3, 1);
        assertEquals(20, s.rows());
        assertEquals(19, s.ok());
        assertEquals(1, s.errors());
        assertEquals(1, ExecutorRenderer.openCount(), "one renderer for the JVM's executor threads");

        // Results: the same ids, statuses and files as batch mode's results.csv; the bad row's error.
        Map<String, CSVRecord> batch = byId(records(batchOut.resolve("results.csv")));
        List<CSVRecord> sparkRows = new ArrayList<>();
        try (Stream<Path> parts = Files.list(sparkOut.resolve("results"))) {
            for (Path p : parts.filter(p -> p.getFileName().toString().startsWith("part-")).sorted().toList()) {
                sparkRows.addAll(records(p));
            }
        }
        Map<String, CSVRecord> spark = byId(sparkRows);
        assertEquals(20, sparkRows.size());
        assertEquals(batch.keySet(), spark.keySet());
        for (String id : batch.keySet()) {
            assertEquals(batch.get(id).get("status"), spark.get(id).get("status"), id);
            assertEquals(batch.get(id).get("files"), spark.get(id).get("files"), id);
        }
        assertEquals("error", spark.get("p13").get("status"));
        assertEquals("row 'p13': latitude 'north' is not a decimal number", spark.get("p13").get("error"));
        assertEquals("line 15: latitude 'north' is not a decimal number", batch.get("p13").get("error"));

        // Every file equal bit for bit, the JSON's timings aside.
        List<String> batchFiles = names(batchOut), sparkFiles = names(sparkOut);
        batchFiles.remove("results.csv");
        sparkFiles.remove("results");
        assertEquals(batchFiles, sparkFiles);
        assertEquals(19 * 4, sparkFiles.size());
        for (String f : batchFiles) {
            byte[] a = Files.readAllBytes(batchOut.resolve(f)), b = Files.readAllBytes(sparkOut.resolve(f));
            if (f.endsWith(".json")) {
                assertEquals(withoutTimings(new String(a, StandardCharsets.UTF_8)), withoutTimings(new String(b, StandardCharsets.UTF_8)), f);
            } else {
                assertArrayEquals(a, b, f + " differs");
            }
        }
    }

    /**
     * Photo rows (an image column, camera values in columns) and rows with the wrong number of fields: the Spark
     * job's files equal {@code dempano batch}'s byte for byte, each bad row is its own error line; and the same
     * table written as Parquet by Spark gives the same files as the CSV.
     */
    @Test
    void photoRowsAndFieldCountErrorsAsInBatchModeAndParquetAsCsv() throws IOException {
        Path dem = DemoTerrain.ensure(tmp.resolve("dem"));
        double[] vp = DemoTerrain.viewpoint();
        Path dir = Files.createDirectories(tmp.resolve("photos"));
        // A generated "photo" (a gradient, no EXIF): its size from the file, its camera from the row.
        java.awt.image.BufferedImage img = new java.awt.image.BufferedImage(160, 120, java.awt.image.BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 120; y++) {
            for (int x = 0; x < 160; x++) {
                img.setRGB(x, y, (x * 255 / 160) << 16 | (y * 255 / 120) << 8 | 128);
            }
        }
        Path photo = dir.resolve("photo.png");
        javax.imageio.ImageIO.write(img, "png", photo.toFile());
        String lat = String.format(Locale.ROOT, "%.4f", vp[0]), lon = String.format(Locale.ROOT, "%.4f", vp[1]);
        String north = String.format(Locale.ROOT, "%.4f", vp[0] + 0.05);
        String header = "id,lat,lon,altitude_m,image,heading_deg,pitch_deg,roll_deg,hfov_deg";
        List<String[]> good = List.of(
                new String[] {"view", lat, lon, "", "", "", "", "", ""},
                new String[] {"east", lat, lon, "", photo.toString(), "90", "-3", "0", "60"},
                // A relative path: relative to the table's folder, as in batch mode (it was the working directory's).
                new String[] {"south", north, lon, "3000", "photos/photo.png", "180", "2", "5", "40"},
                new String[] {"gone", lat, lon, "", dir.resolve("gone.png").toString(), "90", "0", "0", "60"},
                new String[] {"noimage", lat, lon, "", "", "45", "", "", ""});
        StringBuilder text = new StringBuilder(header + "\n");
        good.forEach(r -> text.append(String.join(",", r)).append('\n'));
        text.append("short,").append(lat).append(',').append(lon).append('\n');
        text.append("long,").append(lat).append(',').append(lon).append(",,,,,,,extra\n");
        text.append("VIEW-distance,").append(lat).append(',').append(lon).append(",,,,,,\n"); // would write view's picture
        Path csv = Files.writeString(tmp.resolve("photos.csv"), text.toString(), StandardCharsets.UTF_8);

        Path batchOut = tmp.resolve("photo-batch");
        List<String> batchArgs = new ArrayList<>(List.of(csv.toString(), "--out-dir", batchOut.toString(), "--dem-dir", dem.toString()));
        batchArgs.addAll(List.of(OPTIONS));
        assertEquals(BatchCommand.EXIT_SOME_ROWS_FAILED, new CommandLine(new BatchCommand()).execute(batchArgs.toArray(new String[0])));

        Path sparkOut = tmp.resolve("photo-spark");
        SparkBatchMain main = new SparkBatchMain();
        List<String> sparkArgs = new ArrayList<>(List.of(csv.toString(), "--out-dir", sparkOut.toUri().toString(), "--dem-dir", dem.toString()));
        sparkArgs.addAll(List.of(OPTIONS));
        new CommandLine(main).parseArgs(sparkArgs.toArray(new String[0]));
        JobSettings photoSettings = main.settings();
        photoSettings.tableDir = SparkBatch.tableFolder(spark, csv.toString());
        SparkBatch.Summary s = SparkBatch.run(spark, SparkBatch.read(spark, csv.toString(), null), photoSettings,
                SparkBatch.Order.TILE, 2, 1);
        assertEquals(8, s.rows());
        assertEquals(3, s.ok());

        Map<String, CSVRecord> batch = byId(records(batchOut.resolve("results.csv")));
        Map<String, CSVRecord> sparkResults = byId(sparkRecords(sparkOut));
        assertEquals(batch.keySet(), sparkResults.keySet());
        for (String id : batch.keySet()) {
            assertEquals(batch.get(id).get("status"), sparkResults.get(id).get("status"), id);
            assertEquals(batch.get(id).get("files"), sparkResults.get(id).get("files"), id);
        }
        assertEquals("east.png east-distance.npy east-overlay.png east.json", sparkResults.get("east").get("files"));
        assertEquals("row 'short': 3 fields, the header has 9", sparkResults.get("short").get("error"));
        assertEquals("row 'long': 10 fields, the header has 9", sparkResults.get("long").get("error"));
        assertEquals("line 7: 3 fields, the header has 9", batch.get("short").get("error"));
        assertEquals("row 'VIEW-distance': id 'VIEW-distance' would write view-distance.png, a file of id 'view' (row 'view'):"
                + " choose ids that are not another id with a file suffix", sparkResults.get("VIEW-distance").get("error"));
        assertEquals("line 9: id 'VIEW-distance' would write view-distance.png, a file of id 'view' (line 2): choose ids"
                + " that are not another id with a file suffix", batch.get("VIEW-distance").get("error"));
        assertTrue(sparkResults.get("gone").get("error").contains("gone.png"), sparkResults.get("gone").get("error"));
        assertTrue(sparkResults.get("noimage").get("error").contains("heading_deg is for photo rows"),
                sparkResults.get("noimage").get("error"));
        assertSameFiles(batchOut, sparkOut, 12);

        // The good rows as a Parquet table (numbers as doubles, as a typed table has them) give the same files.
        StructType schema = new StructType().add("id", DataTypes.StringType).add("lat", DataTypes.DoubleType)
                .add("lon", DataTypes.DoubleType).add("altitude_m", DataTypes.DoubleType).add("image", DataTypes.StringType)
                .add("heading_deg", DataTypes.DoubleType).add("pitch_deg", DataTypes.DoubleType)
                .add("roll_deg", DataTypes.DoubleType).add("hfov_deg", DataTypes.DoubleType);
        List<Row> typed = new ArrayList<>();
        for (String[] r : good) {
            Object[] v = new Object[r.length];
            for (int i = 0; i < r.length; i++) {
                boolean isText = i == 0 || i == 4;
                v[i] = r[i].isEmpty() ? null : isText ? r[i] : (Object) Double.parseDouble(r[i]);
            }
            typed.add(RowFactory.create(v));
        }
        String parquet = tmp.resolve("photos.parquet").toString();
        spark.createDataFrame(typed, schema).write().mode("overwrite").parquet(parquet);
        Path parquetOut = tmp.resolve("photo-parquet");
        SparkBatchMain pm = new SparkBatchMain();
        List<String> parquetArgs = new ArrayList<>(List.of(parquet, "--out-dir", parquetOut.toUri().toString(), "--dem-dir", dem.toString()));
        parquetArgs.addAll(List.of(OPTIONS));
        new CommandLine(pm).parseArgs(parquetArgs.toArray(new String[0]));
        JobSettings parquetSettings = pm.settings();
        parquetSettings.tableDir = SparkBatch.tableFolder(spark, parquet);
        SparkBatch.Summary ps = SparkBatch.run(spark, SparkBatch.read(spark, parquet, null), parquetSettings,
                SparkBatch.Order.TILE, 2, 1);
        assertEquals(5, ps.rows());
        assertEquals(3, ps.ok());
        Map<String, CSVRecord> fromParquet = byId(sparkRecords(parquetOut));
        for (String id : fromParquet.keySet()) {
            assertEquals(sparkResults.get(id).get("status"), fromParquet.get(id).get("status"), id);
            assertEquals(sparkResults.get(id).get("files"), fromParquet.get(id).get("files"), id);
        }
        assertSameFiles(sparkOut, parquetOut, 12);
    }

    /** A hostile test's table findings: read as dempano batch reads its file, or refused naming the file. */
    @Test
    void tablesAreReadAsBatchModeReadsThem() throws IOException {
        // A byte-order mark before a quoted header (R's write.csv with UTF-8 BOM): the header's quotes were kept.
        Path bom = tmp.resolve("bom.csv");
        Files.write(bom, ("\uFEFF\"id\",\"lat\",\"lon\"\r\np1,0.1,0.2\r\n").getBytes(StandardCharsets.UTF_8));
        var t = SparkBatch.read(spark, bom.toString(), null);
        assertEquals(List.of("id", "lat", "lon", SparkBatch.FIELDS_ERROR), List.of(t.columns()));
        assertEquals("p1", t.collectAsList().get(0).getString(0));

        // Bytes that are no UTF-8 spoil their row, not the table (batch mode's rule).
        Path latin1 = tmp.resolve("latin1.csv");
        byte[] text = "id,lat,lon,note\nok,0.1,0.2,cafe\nbad,0.1,0.2,caf\u00e9\n".getBytes(StandardCharsets.ISO_8859_1);
        Files.write(latin1, text);
        List<Row> rows = SparkBatch.read(spark, latin1.toString(), null).collectAsList();
        assertEquals(null, rows.get(0).getString(4));
        assertTrue(rows.get(1).getString(4).startsWith("not UTF-8 text"), rows.get(1).getString(4));

        // A folder of CSV files whose headers differ: refused (the second was read into the first's columns).
        Path folder = Files.createDirectories(tmp.resolve("mixed-headers"));
        Files.writeString(folder.resolve("a.csv"), "id,lat,lon\nf1,0.1,0.2\n");
        Files.writeString(folder.resolve("b.csv"), "id,lon,lat\nf2,0.2,0.1\n");
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> SparkBatch.read(spark, folder.toString(), null));
        assertTrue(e.getMessage().contains("b.csv: its header line (id,lon,lat) differs from a.csv's (id,lat,lon)"), e.getMessage());
    }

    /** The output folder: one job at a time, a file is no folder, a folder in the way of a row's file is that row's error. */
    @Test
    void theOutputFolderIsOneJobsAtATime() throws IOException {
        Path dem = DemoTerrain.ensure(tmp.resolve("dem"));
        double[] vp = DemoTerrain.viewpoint();
        Path out = tmp.resolve("claimed");
        org.apache.hadoop.conf.Configuration conf = spark.sparkContext().hadoopConfiguration();
        org.apache.hadoop.fs.Path lock = SparkBatch.claim(out.toString(), conf);
        SparkBatch.OutputFolderException twice = org.junit.jupiter.api.Assertions.assertThrows(
                SparkBatch.OutputFolderException.class, () -> SparkBatch.claim(out.toString(), conf));
        assertTrue(twice.getMessage().startsWith("another job is writing into " + out), twice.getMessage());

        // A job into the claimed folder is refused and writes nothing (two jobs lost and mixed each other's lines).
        String lat = String.format(Locale.ROOT, "%.4f", vp[0]), lon = String.format(Locale.ROOT, "%.4f", vp[1]);
        Path csv = Files.writeString(tmp.resolve("claimed.csv"), "id,lat,lon\np,%s,%s\n".formatted(lat, lon));
        SparkBatchMain main = new SparkBatchMain();
        List<String> args = new ArrayList<>(List.of(csv.toString(), "--out-dir", out.toString(), "--dem-dir", dem.toString()));
        args.addAll(List.of(OPTIONS));
        new CommandLine(main).parseArgs(args.toArray(new String[0]));
        org.junit.jupiter.api.Assertions.assertThrows(SparkBatch.OutputFolderException.class, () -> SparkBatch.run(spark,
                SparkBatch.read(spark, csv.toString(), null), main.settings(), SparkBatch.Order.TILE, 1, 1));
        assertEquals(List.of(SparkBatch.LOCK_FILE), names(out).stream().filter(n -> !n.endsWith(".crc")).toList());
        lock.getFileSystem(conf).delete(lock, false);

        // Ids trimmed as CSV cells are (a Parquet ' a' wrote over 'a''s files, both "ok"); an id with a line break is
        // written with '?' and counted once; a folder in the way of a row's file is that row's error.
        Files.createDirectories(out.resolve("q-distance.png"));
        StructType schema = new StructType().add("id", DataTypes.StringType).add("lat", DataTypes.StringType)
                .add("lon", DataTypes.StringType);
        List<Row> table = List.of(RowFactory.create("a", lat, lon), RowFactory.create(" a", lat, lon),
                RowFactory.create("n\nl", lat, lon), RowFactory.create("q", lat, lon));
        SparkBatch.Summary s = SparkBatch.run(spark, spark.createDataFrame(table, schema), main.settings(),
                SparkBatch.Order.INPUT, 2, 1);
        assertEquals(4, s.rows());
        assertEquals(1, s.ok());
        List<CSVRecord> results = sparkRecords(out);
        assertEquals(List.of("a", "a", "n?l", "q"), results.stream().map(r -> r.get("id")).sorted().toList());
        assertEquals(1, results.stream().filter(r -> r.get("id").equals("a") && r.get("status").equals("ok")).count());
        assertTrue(results.stream().anyMatch(r -> r.get("error").contains("duplicate id 'a'")), results.toString());
        CSVRecord q = results.stream().filter(r -> r.get("id").equals("q")).findFirst().orElseThrow();
        assertTrue(q.get("error").contains("q-distance.png: a folder of that name is in the way"), q.get("error"));
        assertTrue(Files.isDirectory(out.resolve("q-distance.png")) && names(out.resolve("q-distance.png")).isEmpty());
        assertTrue(!Files.exists(out.resolve("q.json")), "no json claims q's set complete");
        assertTrue(!Files.exists(out.resolve(SparkBatch.LOCK_FILE)), "the job's claim is released");

        // An output folder that is a file.
        Path file = Files.writeString(tmp.resolve("a-file"), "x");
        SparkBatch.OutputFolderException isFile = org.junit.jupiter.api.Assertions.assertThrows(
                SparkBatch.OutputFolderException.class, () -> SparkBatch.claim(file.toString(), conf));
        assertTrue(isFile.getMessage().contains("is a file"), isFile.getMessage());
    }

    /**
     * Relative --out-dir and --dem-dir are the driver's (on a cluster an executor resolved them against its own working
     * folder: every row's files lost there, or every row failed); a second job's results table replaces the first's
     * whole, written beside it until then (a job killed midway left no table at all).
     */
    @Test
    void relativePathsAreTheDriversAndTheResultsTableIsReplacedWhole() throws IOException {
        Path dem = DemoTerrain.ensure(tmp.resolve("dem"));
        double[] vp = DemoTerrain.viewpoint();
        Path cwd = Path.of("").toAbsolutePath();
        Path out = tmp.resolve("relative-out");
        String lat = String.format(Locale.ROOT, "%.4f", vp[0]), lon = String.format(Locale.ROOT, "%.4f", vp[1]);
        for (String ids : new String[] {"first", "second"}) {
            Path csv = Files.writeString(tmp.resolve(ids + ".csv"), "id,lat,lon\n%s,%s,%s\n".formatted(ids, lat, lon));
            SparkBatchMain main = new SparkBatchMain();
            List<String> args = new ArrayList<>(List.of(csv.toString(), "--out-dir", cwd.relativize(out).toString(),
                    "--dem-dir", cwd.relativize(dem).toString()));
            args.addAll(List.of(OPTIONS));
            new CommandLine(main).parseArgs(args.toArray(new String[0]));
            JobSettings settings = main.settings();
            SparkBatch.Summary s = SparkBatch.run(spark, SparkBatch.read(spark, csv.toString(), null), settings,
                    SparkBatch.Order.INPUT, 1, 1);
            assertEquals(1, s.ok(), s.toString());
            // What the executors were given: absolute paths.
            assertEquals(out.toString(), settings.outDir);
            assertEquals(List.of(dem.toString()), settings.demDirs);
            assertEquals(List.of(ids), sparkRecords(out).stream().map(r -> r.get("id")).toList(), "the table of this job only");
            assertTrue(Files.exists(out.resolve(ids + ".json")));
            assertTrue(!Files.exists(out.resolve(SparkBatch.RESULTS_WRITING)), "nothing left beside the table");
        }
        assertEquals(out.toString(), SparkBatch.qualified(spark, cwd.relativize(out).toString()));
        assertEquals("hdfs://nn:8020/x/out", SparkBatch.qualified(spark, "hdfs://nn:8020/x/out"));
    }

    @Test
    void executorsWithoutTheJobJarAreSaidSo() {
        var stageFailure = new RuntimeException("Job aborted due to stage failure: Task 0 in stage 1.0 failed 4 times: "
                + "java.lang.ClassCastException: cannot assign instance of java.lang.invoke.SerializedLambda to field "
                + "org.apache.spark.rdd.MapPartitionsRDD.f");
        assertTrue(SparkBatchMain.missingClassesHint(stageFailure).contains("submit the job jar with spark-submit"));
        assertTrue(SparkBatchMain.missingClassesHint(new RuntimeException("wrapped",
                new ClassNotFoundException("dempano.spark.SparkBatch$RenderPartition"))).contains("spark.jars"));
        assertEquals("", SparkBatchMain.missingClassesHint(new RuntimeException("Path does not exist: file:/x.csv")));
    }

    /** A DEM folder named by a plain path with URI syntax in it ('%', '[') is that folder (every row failed). */
    @Test
    void aPlainDemPathIsNotReadAsAUri() {
        JobSettings s = new JobSettings();
        assertEquals(Path.of("/data/dem%x[1]"), ExecutorRenderer.localDem("/data/dem%x[1]", s));
        assertEquals(Path.of("/data/dem 1"), ExecutorRenderer.localDem("file:///data/dem%201", s));
    }

    static List<CSVRecord> sparkRecords(Path out) throws IOException {
        List<CSVRecord> rows = new ArrayList<>();
        try (Stream<Path> parts = Files.list(out.resolve("results"))) {
            for (Path p : parts.filter(p -> p.getFileName().toString().startsWith("part-")).sorted().toList()) {
                rows.addAll(records(p));
            }
        }
        return rows;
    }

    /** The same file names in both folders (results aside), every file equal bit for bit, the JSON's timings aside. */
    static void assertSameFiles(Path a, Path b, int count) throws IOException {
        List<String> as = names(a), bs = names(b);
        as.removeAll(List.of("results.csv", "results"));
        bs.removeAll(List.of("results.csv", "results"));
        assertEquals(as, bs);
        assertEquals(count, as.size(), as.toString());
        for (String f : as) {
            byte[] x = Files.readAllBytes(a.resolve(f)), y = Files.readAllBytes(b.resolve(f));
            if (f.endsWith(".json")) {
                assertEquals(withoutTimings(new String(x, StandardCharsets.UTF_8)), withoutTimings(new String(y, StandardCharsets.UTF_8)), f);
            } else {
                assertArrayEquals(x, y, f + " differs");
            }
        }
    }

    /** The JSON with its timing values blanked (they differ from run to run). */
    static String withoutTimings(String json) {
        return json.replaceAll("\"timingsMillis\"\\s*:\\s*\\{[^}]*}", "\"timingsMillis\": {}");
    }

    static List<String> names(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().collect(Collectors.toCollection(ArrayList::new));
        }
    }

    static List<CSVRecord> records(Path file) throws IOException {
        try (CSVParser p = CSVParser.parse(Files.readString(file, StandardCharsets.UTF_8),
                CSVFormat.DEFAULT.builder().setHeader().setSkipHeaderRecord(true).get())) {
            assertEquals(SparkBatch.RESULT_COLUMNS, p.getHeaderNames());
            return p.getRecords();
        }
    }

    static Map<String, CSVRecord> byId(List<CSVRecord> rows) {
        Map<String, CSVRecord> m = new TreeMap<>();
        rows.forEach(r -> assertTrue(m.put(r.get("id"), r) == null, "one line per id"));
        return m;
    }
}

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
import org.apache.spark.sql.SparkSession;
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

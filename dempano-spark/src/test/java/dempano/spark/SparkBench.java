package dempano.spark;

import dempano.bench.FractalRelief;
import dempano.cli.BatchCommand;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.apache.spark.sql.SparkSession;
import picocli.CommandLine;

/**
 * {@code gradle :dempano-spark:benchSpark}: seconds per panorama on this machine, dempano batch
 * against the Spark job in local mode, rows ordered by tile and at random. A generated relief of
 * 4 × 5 SRTM3 tiles (more than the DEM folder's 16 cached tiles), viewpoints at random over it.
 * Spark runs alternate random, tile, random, tile (the first run also warms the JVM). Prints a Markdown table.
 * Arguments: WORKDIR [ROWS [PPD [RANGE_KM [THREADS [nobatch]]]]].
 */
public final class SparkBench {
    public static void main(String[] args) throws Exception {
        Path work = Path.of(args.length > 0 ? args[0] : "/tmp/dempano-spark-bench");
        int rows = args.length > 1 ? Integer.parseInt(args[1]) : 60;
        String ppd = args.length > 2 ? args[2] : "4";
        String rangeKm = args.length > 3 ? args[3] : "30";
        int threads = args.length > 4 ? Integer.parseInt(args[4]) : 2;
        Path dem = FractalRelief.ensure(work.resolve("dem"), 45, 6, 4, 5, 1201);
        Random rnd = new Random(7);
        StringBuilder csv = new StringBuilder("id,lat,lon\n");
        for (int i = 0; i < rows; i++) {
            csv.append(String.format(Locale.ROOT, "v%04d,%.5f,%.5f%n", i, 45.05 + 3.9 * rnd.nextDouble(), 6.05 + 4.9 * rnd.nextDouble()));
        }
        Path viewpoints = work.resolve("viewpoints.csv");
        Files.writeString(viewpoints, csv, StandardCharsets.UTF_8);
        String[] options = {"--ppd", ppd, "--range-km", rangeKm, "--elevation-range", "-10:10"};
        List<String> table = new ArrayList<>();
        table.add("| run | rows | wall s | s per panorama | panoramas per hour |");
        table.add("|---|---:|---:|---:|---:|");

        List<String> a = new ArrayList<>(List.of(viewpoints.toString(), "--out-dir", work.resolve("out-batch").toString(),
                "--dem-dir", dem.toString()));
        a.addAll(List.of(options));
        if (!(args.length > 5 && args[5].equals("nobatch"))) {
            long t0 = System.nanoTime();
            int code = new CommandLine(new BatchCommand()).execute(a.toArray(new String[0]));
            double batch = (System.nanoTime() - t0) / 1e9;
            table.add(row("dempano batch (one process, rows in file order = random)", rows, batch));
            if (code != 0) {
                throw new IllegalStateException("dempano batch exited with " + code);
            }
        }

        SparkSession spark = SparkSession.builder().master("local[" + threads + "]").appName("dempano-spark-bench")
                .config("spark.ui.enabled", "false").config("spark.driver.host", "127.0.0.1").getOrCreate();
        try {
            for (SparkBatch.Order order : new SparkBatch.Order[] {SparkBatch.Order.RANDOM,
                    SparkBatch.Order.TILE, SparkBatch.Order.RANDOM, SparkBatch.Order.TILE}) {
                ExecutorRenderer.closeAll(); // each run starts with cold caches, as a fresh executor would
                SparkBatchMain m = new SparkBatchMain();
                List<String> b = new ArrayList<>(List.of(viewpoints.toString(), "--out-dir",
                        work.resolve("out-" + order.name().toLowerCase(Locale.ROOT)).toUri().toString(), "--dem-dir", dem.toString()));
                b.addAll(List.of(options));
                new CommandLine(m).parseArgs(b.toArray(new String[0]));
                long t1 = System.nanoTime();
                SparkBatch.Summary s = SparkBatch.run(spark, SparkBatch.read(spark, viewpoints.toString(), null), m.settings(),
                        order, 2 * threads, 1);
                double sec = (System.nanoTime() - t1) / 1e9;
                if (s.errors() != 0) {
                    throw new IllegalStateException(s.errors() + " rows failed: see " + s.results());
                }
                table.add(row("Spark local[" + threads + "], " + 2 * threads + " tasks, order " + order.name().toLowerCase(Locale.ROOT),
                        rows, sec));
            }
        } finally {
            spark.stop();
            ExecutorRenderer.closeAll();
        }
        System.out.println();
        System.out.println("ppd " + ppd + ", range " + rangeKm + " km, elevation -10:10, " + Runtime.getRuntime().availableProcessors()
                + " cores, heap " + Runtime.getRuntime().maxMemory() / (1 << 20) + " MiB");
        table.forEach(System.out::println);
        System.exit(0);
    }

    private static String row(String name, int rows, double seconds) {
        return String.format(Locale.ROOT, "| %s | %d | %.1f | %.2f | %.0f |", name, rows, seconds, seconds / rows, rows / seconds * 3600);
    }
}

package dempano.spark;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import dempano.cli.PanoramaOptions;
import java.util.concurrent.Callable;
import org.apache.spark.sql.SparkSession;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code spark-submit --class dempano.spark.SparkBatchMain dempano-spark-job.jar VIEWPOINTS --out-dir D --dem-dir DIR}:
 * {@code dempano batch} on a Spark cluster (see {@link SparkBatch} and docs/spark.md). The options
 * are {@code dempano batch}'s, as defaults for every row, plus how rows are spread over tasks.
 */
@Command(name = "dempano-spark", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Renders the panorama of every row of a viewpoint table (CSV with a header line, or Parquet) on Spark.",
                "Columns: id, lat, lon (required); altitude_m, offset_m, eye_height_m, range_km, ppd (optional), as for dempano batch."},
        footer = {"", "Writes D/<id>.png, D/<id>-distance.npy, D/<id>-distance.png, D/<id>.json per row (D: any Hadoop-compatible "
                + "path) and the results table D/results/part-*.csv (id,status,files,seconds,error).",
                "Exit codes: 0 every row done, 3 some rows failed (see the results), 1 unusable table or output folder, 2 bad arguments."})
public final class SparkBatchMain implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "VIEWPOINTS", description = "Viewpoint table: CSV (header line) or Parquet (path ending in .parquet, or --format).")
    String viewpoints;
    @Option(names = "--format", paramLabel = "csv|parquet", description = "Table format (default: from the name).")
    String format;
    @Option(names = "--out-dir", required = true, paramLabel = "D", description = "Output folder: a local path or a Hadoop URI (hdfs://, s3a://, …).")
    String outDir;
    @Option(names = "--dem-dir", required = true, paramLabel = "DIR", description = "DEM folder: a path present on every node, "
            + "or a Hadoop URI copied to each node once; repeatable, in priority order.")
    List<String> demDirs;
    @Option(names = "--order", paramLabel = "tile|random|input", description = "How rows are spread over tasks (default: ${DEFAULT-VALUE}).", defaultValue = "tile")
    String order;
    @Option(names = "--partitions", description = "Tasks (default: rows / 100, at least twice the default parallelism).", defaultValue = "0")
    int partitions;
    @Option(names = "--seed", description = "Seed of --order random (default: ${DEFAULT-VALUE}).", defaultValue = "1")
    long seed;
    /** The panorama options of {@code dempano} and {@code dempano batch}: every row's defaults. */
    @CommandLine.Mixin
    PanoramaOptions panorama = new PanoramaOptions();

    /** The job settings from the options. */
    JobSettings settings() {
        JobSettings s = new JobSettings();
        s.demDirs = new ArrayList<>(demDirs);
        s.outDir = outDir;
        s.panorama = panorama;
        return s;
    }

    @Override
    public Integer call() {
        JobSettings s = settings();
        SparkBatch.Order o;
        try {
            s.check();
            if (!List.of("tile", "random", "input").contains(order.toLowerCase(Locale.ROOT))) {
                throw new IllegalArgumentException("--order must be tile, random or input, got '" + order + "'");
            }
            o = SparkBatch.Order.valueOf(order.toUpperCase(Locale.ROOT));
            if (format != null && !List.of("csv", "parquet").contains(format.toLowerCase(Locale.ROOT))) {
                throw new IllegalArgumentException("--format must be csv or parquet, got '" + format + "'");
            }
        } catch (IllegalArgumentException e) {
            System.err.println("dempano-spark: " + e.getMessage());
            return 2;
        }
        SparkSession spark = SparkSession.builder().appName("dempano-spark").getOrCreate();
        try {
            // Every problem with the table or the output folder is one line and exit 1, never a stack trace: Spark's and
            // Hadoop's exceptions (a missing or corrupt Parquet table, an output folder that is a file) included.
            SparkBatch.Summary sum;
            int n = partitions;
            try {
                var table = SparkBatch.read(spark, viewpoints, format);
                s.tableDir = SparkBatch.tableFolder(spark, viewpoints);
                if (n <= 0) {
                    long rows = table.count();
                    n = (int) Math.max(2L * spark.sparkContext().defaultParallelism(), (rows + 99) / 100);
                }
                sum = SparkBatch.run(spark, table, s, o, n, seed);
            } catch (SparkBatch.OutputFolderException e) {
                System.err.println("dempano-spark: " + e.getMessage());
                return 1;
            } catch (IllegalArgumentException e) {
                System.err.println("dempano-spark: " + (e.getMessage().startsWith(viewpoints) ? "" : viewpoints + ": ")
                        + e.getMessage());
                return 1;
            } catch (Exception e) {
                System.err.println("dempano-spark: " + oneLine(e) + missingClassesHint(e));
                return 1;
            }
            System.err.printf(Locale.ROOT, "dempano-spark: %d ok, %d failed of %d rows in %.1f s (%d tasks, order %s); results in %s%n",
                    sum.ok(), sum.errors(), sum.rows(), sum.seconds(), n, o.name().toLowerCase(Locale.ROOT), sum.results());
            return sum.errors() == 0 ? 0 : 3;
        } finally {
            spark.stop();
        }
    }

    /** An exception's message on one line (Spark's carry a query plan after a line break), with its cause's. */
    static String oneLine(Throwable e) {
        String m = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage().strip().split("\\R", 2)[0];
        Throwable c = e.getCause();
        if (c != null && c.getMessage() != null && !m.contains(c.getMessage().strip().split("\\R", 2)[0])) {
            m += ": " + c.getMessage().strip().split("\\R", 2)[0];
        }
        return m;
    }

    /**
     * What a failure that shows the executors lack dempano's classes means, or "": the job started with {@code java -cp}
     * and no {@code spark.jars} aborts after four attempts a task with a ClassCastException about a SerializedLambda
     * (or a ClassNotFoundException for a dempano class), which says nothing of the jar.
     */
    static String missingClassesHint(Throwable e) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            String m = String.valueOf(t.getMessage());
            boolean classMissing = (t instanceof ClassNotFoundException || t instanceof NoClassDefFoundError)
                    && m.replace('/', '.').startsWith("dempano.");
            if (classMissing || m.contains("cannot assign instance of java.lang.invoke.SerializedLambda")
                    || m.matches("(?s).*(ClassNotFoundException|NoClassDefFoundError)\\W+dempano[./].*")) {
                return " (the executors do not have dempano's classes: submit the job jar with spark-submit, which ships it"
                        + " to them, or list it in spark.jars)";
            }
        }
        return "";
    }

    public static void main(String[] args) {
        int code = new CommandLine(new SparkBatchMain()).execute(args);
        System.exit(code);
    }
}

package dempano.spark;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
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
                "Exit codes: 0 every row done, 3 some rows failed (see the results), 1 unusable input, 2 bad arguments."})
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
    @Option(names = "--ppd", defaultValue = "20", description = "Pixels per degree (default: ${DEFAULT-VALUE}; column ppd).")
    double ppd;
    @Option(names = "--range-km", defaultValue = "100", description = "Range of sight, km (default: ${DEFAULT-VALUE}; column range_km).")
    double rangeKm;
    @Option(names = "--offset-m", defaultValue = "0", description = "Altitude correction, metres (default: ${DEFAULT-VALUE}; column offset_m).")
    double offsetMetres;
    @Option(names = "--eye-height-m", defaultValue = "2", description = "Eye above the standing altitude, metres (default: ${DEFAULT-VALUE}; column eye_height_m).")
    double eyeHeightMetres;
    @Option(names = "--refraction", paramLabel = "K", defaultValue = "0.13", description = "Refraction coefficient (default: ${DEFAULT-VALUE}).")
    double refraction;
    @Option(names = "--elevation-range", paramLabel = "BOTTOM:TOP|auto", defaultValue = "-30:30", description = "Elevation angles, degrees (default: ${DEFAULT-VALUE}).")
    String elevationRange;
    @Option(names = "--depth-mode", paramLabel = "MODE", defaultValue = "shader", description = "shader (default), reversed32f or standard24.")
    String depthMode;
    @Option(names = "--layers", split = ",", paramLabel = "LAYER", description = "Extra per-pixel layers.")
    List<String> layers;
    @Option(names = "--pfm", description = "Distance maps as .pfm instead of .npy.")
    boolean pfm;
    @Option(names = "--near-m", defaultValue = "1", description = "Near plane, metres (default: ${DEFAULT-VALUE}).")
    double nearMetres;
    @Option(names = "--supersampling", defaultValue = "1", description = "View pixels per panorama pixel (default: ${DEFAULT-VALUE}).")
    double supersampling;
    @Option(names = "--views", defaultValue = "8", description = "Perspective views (default: ${DEFAULT-VALUE}).")
    int views;
    @Option(names = "--lod-px", paramLabel = "PX", defaultValue = "" + dempano.terrain.LevelOfDetail.DEFAULT_MAX_ERROR_PX,
            description = "Level-of-detail screen error bound, pixels (default: ${DEFAULT-VALUE}).")
    double lodErrorPx;
    @Option(names = "--exact-distances", negatable = true, defaultValue = "true", fallbackValue = "true",
            description = "Every pixel's distance along its own ray (default); --no-exact-distances interpolates.")
    boolean exactDistances;
    @Option(names = "--no-colour", description = "Distances only.")
    boolean noColour;
    @Option(names = "--no-distance", description = "Colour only.")
    boolean noDistance;
    @Option(names = "--missing-tiles", paramLabel = "auto|sea|error", defaultValue = "auto", description = "A needed tile that is absent (default: ${DEFAULT-VALUE}).")
    String missingTiles;
    @Option(names = "--renderer", paramLabel = "opengl|reference", defaultValue = "opengl", description = "opengl (default) or reference (CPU).")
    String renderer;

    /** The job settings from the options. */
    JobSettings settings() {
        JobSettings s = new JobSettings();
        s.demDirs = new ArrayList<>(demDirs);
        s.outDir = outDir;
        s.ppd = ppd;
        s.rangeKm = rangeKm;
        s.offsetMetres = offsetMetres;
        s.eyeHeightMetres = eyeHeightMetres;
        s.refraction = refraction;
        s.elevationRange = elevationRange;
        s.depthMode = depthMode;
        s.layers = layers == null ? new ArrayList<>() : new ArrayList<>(layers);
        s.pfm = pfm;
        s.nearMetres = nearMetres;
        s.supersampling = supersampling;
        s.views = views;
        s.lodErrorPx = lodErrorPx;
        s.exactDistances = exactDistances;
        s.colour = !noColour;
        s.distance = !noDistance;
        s.missingTiles = missingTiles;
        s.renderer = renderer;
        return s;
    }

    @Override
    public Integer call() {
        JobSettings s = settings();
        SparkBatch.Order o;
        try {
            s.check();
            o = SparkBatch.Order.valueOf(order.toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            System.err.println("dempano-spark: " + e.getMessage());
            return 2;
        }
        SparkSession spark = SparkSession.builder().appName("dempano-spark").getOrCreate();
        try {
            var table = SparkBatch.read(spark, viewpoints, format);
            int n = partitions;
            if (n <= 0) {
                long rows = table.count();
                n = (int) Math.max(2L * spark.sparkContext().defaultParallelism(), (rows + 99) / 100);
            }
            SparkBatch.Summary sum;
            try {
                sum = SparkBatch.run(spark, table, s, o, n, seed);
            } catch (IllegalArgumentException e) {
                System.err.println("dempano-spark: " + viewpoints + ": " + e.getMessage());
                return 1;
            }
            System.err.printf(Locale.ROOT, "dempano-spark: %d ok, %d failed of %d rows in %.1f s (%d tasks, order %s); results in %s%n",
                    sum.ok(), sum.errors(), sum.rows(), sum.seconds(), n, o.name().toLowerCase(Locale.ROOT), sum.results());
            return sum.errors() == 0 ? 0 : 3;
        } finally {
            spark.stop();
        }
    }

    public static void main(String[] args) {
        int code = new CommandLine(new SparkBatchMain()).execute(args);
        System.exit(code);
    }
}

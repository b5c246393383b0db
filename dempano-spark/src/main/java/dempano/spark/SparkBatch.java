package dempano.spark;

import static org.apache.spark.sql.functions.array;
import static org.apache.spark.sql.functions.coalesce;
import static org.apache.spark.sql.functions.col;
import static org.apache.spark.sql.functions.explode;
import static org.apache.spark.sql.functions.concat;
import static org.apache.spark.sql.functions.first;
import static org.apache.spark.sql.functions.floor;
import static org.apache.spark.sql.functions.length;
import static org.apache.spark.sql.functions.lit;
import static org.apache.spark.sql.functions.lower;
import static org.apache.spark.sql.functions.min;
import static org.apache.spark.sql.functions.monotonically_increasing_id;
import static org.apache.spark.sql.functions.rand;
import static org.apache.spark.sql.functions.row_number;
import static org.apache.spark.sql.functions.when;

import dempano.batch.ViewpointCsv;
import java.io.Serializable;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.NoSuchElementException;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVParser;
import org.apache.commons.csv.CSVRecord;
import org.apache.spark.api.java.JavaRDD;
import org.apache.spark.api.java.function.FlatMapFunction;
import org.apache.spark.sql.Column;
import org.apache.spark.sql.Dataset;
import org.apache.spark.sql.Row;
import org.apache.spark.sql.RowFactory;
import org.apache.spark.sql.SparkSession;
import org.apache.spark.sql.expressions.Window;
import org.apache.spark.sql.types.DataTypes;
import org.apache.spark.sql.types.StructType;

/**
 * The batch job on Spark: every row of a viewpoint table (CSV with a header line, or Parquet; the
 * columns of {@code dempano batch}: id, lat, lon, altitude_m, offset_m, eye_height_m, range_km, ppd)
 * rendered on the executors, one renderer per executor JVM ({@link ExecutorRenderer}), each row's
 * files written to the output folder (any Hadoop-compatible path) and a results table
 * {@code OUT/results/part-*.csv} (id,status,files,seconds,error). A row that fails is an error line
 * in the results; the job goes on.
 *
 * <p>Rows are ordered by DEM tile ({@link Order#TILE}): range-partitioned on (floor(lat), floor(lon),
 * lat, lon) and sorted within each partition, so that a task's rows share tiles and the executor's
 * caches serve them; {@link Order#RANDOM} is there to measure what that buys.
 */
public final class SparkBatch {
    /** How rows are spread over tasks. */
    public enum Order {
        /** By DEM tile, then position (the default). */
        TILE,
        /** Shuffled (to measure the tile order's gain). */
        RANDOM,
        /** As read. */
        INPUT
    }

    /** Columns of the results table, as {@code dempano batch} writes {@code results.csv}. */
    public static final List<String> RESULT_COLUMNS = List.of("id", "status", "files", "seconds", "error");

    /** The outcome of a job: counts from the results table and where it is. */
    public record Summary(long rows, long ok, long errors, double seconds, String results) {
    }

    private static final String NAME = "_dempano_file", CLASH_SEQ = "_dempano_clash_seq", CLASH_ID = "_dempano_clash_id",
            FIRST_ID = "_dempano_first_id", CLASH = "_dempano_clash";
    private static final String SEQ = "_dempano_seq", DUP = "_dempano_duplicate_of", TLAT = "_dempano_tile_lat",
            TLON = "_dempano_tile_lon", LAT = "_dempano_lat", LON = "_dempano_lon", KEY = "_dempano_key";

    private SparkBatch() {
    }

    /**
     * The column that carries a CSV row's field-count error ("3 fields, the header has 5"; null for a good row):
     * that row is an error line in the results, as in {@code dempano batch}.
     */
    public static final String FIELDS_ERROR = "_dempano_fields_error";

    /**
     * Reads a viewpoint table: Parquet when the path ends in .parquet (or format says so), else CSV with
     * a header line, parsed as {@code dempano batch} parses it (commons-csv: RFC 4180 quoting, cells trimmed,
     * blank lines skipped, every cell text). A CSV row with more or fewer fields than the header is kept with
     * its field-count error in {@link #FIELDS_ERROR} (Spark's own CSV reader fills or drops such fields
     * silently). The CSV is parsed on the driver (a folder: its files in name order, the first one's header
     * line for all), so its rows must fit in the driver's memory: about 200 bytes a row, 200 MB for 10^6 rows.
     *
     * @throws IllegalArgumentException naming the file, for a file that cannot be read, is empty or broken
     */
    public static Dataset<Row> read(SparkSession spark, String input, String format) {
        boolean parquet = "parquet".equalsIgnoreCase(format)
                || (!"csv".equalsIgnoreCase(format) && input.toLowerCase(Locale.ROOT).replaceAll("/+$", "").endsWith(".parquet"));
        if (parquet) {
            return spark.read().parquet(input);
        }
        List<String> header = null;
        List<Row> rows = new ArrayList<>();
        try {
            org.apache.hadoop.fs.Path in = new org.apache.hadoop.fs.Path(input);
            org.apache.hadoop.fs.FileSystem fs = in.getFileSystem(spark.sparkContext().hadoopConfiguration());
            List<org.apache.hadoop.fs.Path> files = new ArrayList<>();
            if (fs.getFileStatus(in).isDirectory()) {
                for (org.apache.hadoop.fs.FileStatus st : fs.listStatus(in)) {
                    String n = st.getPath().getName();
                    if (st.isFile() && !n.startsWith(".") && !n.startsWith("_")) {
                        files.add(st.getPath());
                    }
                }
                files.sort(java.util.Comparator.comparing(org.apache.hadoop.fs.Path::getName));
            } else {
                files.add(in);
            }
            CSVFormat csv = CSVFormat.DEFAULT.builder().setIgnoreEmptyLines(true).setIgnoreSurroundingSpaces(true)
                    .setTrim(true).get();
            org.apache.hadoop.fs.Path headerFile = null;
            for (org.apache.hadoop.fs.Path f : files) {
                boolean headerLine = true;
                byte[] bytes;
                try (java.io.InputStream stream = fs.open(f)) {
                    bytes = stream.readAllBytes();
                }
                // As dempano batch reads its file: a byte-order mark skipped before parsing (a quoted first header cell
                // after one was read as a literal '"id"'), bytes that are no UTF-8 spoil their rows, not the table.
                ViewpointCsv.Decoded decoded = ViewpointCsv.decode(bytes);
                boolean malformed = decoded.malformed();
                try (CSVParser parser = CSVParser.parse(decoded.text(), csv)) {
                    for (CSVRecord rec : parser) {
                        List<String> cells = rec.toList();
                        if (cells.stream().allMatch(String::isEmpty)) {
                            continue;
                        }
                        boolean notUtf8 = malformed && cells.stream().anyMatch(v -> v.indexOf('\uFFFD') >= 0);
                        if (headerLine) {
                            headerLine = false;
                            if (notUtf8) {
                                throw new IllegalArgumentException(f + ": header line: not UTF-8 text (save the file as UTF-8)");
                            }
                            if (header == null) {
                                header = cells;
                                headerFile = f;
                            } else if (!cells.equals(header)) {
                                // The first file's header is every file's: one that orders or names its columns otherwise
                                // would be read into the wrong columns.
                                throw new IllegalArgumentException(f + ": its header line (" + String.join(",", cells)
                                        + ") differs from " + headerFile.getName() + "'s (" + String.join(",", header)
                                        + "): every file of a table folder must have the same columns in the same order");
                            }
                            continue;
                        }
                        Object[] values = new Object[header.size() + 1];
                        for (int i = 0; i < header.size(); i++) {
                            values[i] = i < cells.size() && !cells.get(i).isEmpty() ? cells.get(i) : null;
                        }
                        if (notUtf8) {
                            values[header.size()] = ViewpointCsv.NOT_UTF8;
                        } else if (cells.size() != header.size()) {
                            values[header.size()] = cells.size() + " fields, the header has " + header.size();
                        }
                        rows.add(RowFactory.create(values));
                    }
                } catch (java.io.UncheckedIOException | IllegalStateException e) {
                    throw new IllegalArgumentException(f + ": broken CSV (" + e.getMessage() + ")", e);
                }
            }
        } catch (java.io.IOException e) {
            throw new IllegalArgumentException("cannot read the viewpoint table " + input + ": " + e.getMessage(), e);
        }
        if (header == null) {
            throw new IllegalArgumentException(input + ": empty: want a header line naming the columns id,lat,lon");
        }
        StructType schema = new StructType();
        for (String h : header) {
            schema = schema.add(h, DataTypes.StringType);
        }
        schema = schema.add(FIELDS_ERROR, DataTypes.StringType);
        return spark.createDataFrame(rows, schema);
    }

    /**
     * The folder a viewpoint table is in (for a table that is a folder, a Parquet table or a folder of CSV files, the
     * folder that holds it), for relative image paths, as {@code dempano batch} takes them from its file's folder: a
     * local path for a local table, else the Hadoop URI.
     */
    public static String tableFolder(SparkSession spark, String input) {
        try {
            org.apache.hadoop.fs.Path in = new org.apache.hadoop.fs.Path(input);
            org.apache.hadoop.fs.FileSystem fs = in.getFileSystem(spark.sparkContext().hadoopConfiguration());
            org.apache.hadoop.fs.Path q = fs.makeQualified(in);
            fs.getFileStatus(q); // it exists
            org.apache.hadoop.fs.Path dir = q.getParent();
            return "file".equals(dir.toUri().getScheme()) ? java.nio.file.Path.of(dir.toUri()).toString() : dir.toString();
        } catch (java.io.IOException e) {
            throw new IllegalArgumentException("cannot read the viewpoint table " + input + ": " + e.getMessage(), e);
        }
    }

    /** Renders every row of the table; see the class comment. */
    public static Summary run(SparkSession spark, Dataset<Row> table, JobSettings settings, Order order, int partitions,
                              long seed) {
        long t0 = System.nanoTime();
        settings.hadoop = Hadoop.settings(spark.sparkContext().hadoopConfiguration());
        settings.check();
        // Paths as the driver means them: an executor resolves a relative one against its own working folder (a relative
        // --out-dir put every row's files there, lost, while the driver said "ok"; a relative --dem-dir failed every row).
        settings.outDir = qualified(spark, settings.outDir);
        List<String> demDirs = new ArrayList<>();
        for (String d : settings.demDirs) {
            if (Hadoop.isUri(d)) {
                demDirs.add(d);
                continue;
            }
            java.nio.file.Path dir = java.nio.file.Path.of(d).toAbsolutePath().normalize();
            if (!java.nio.file.Files.isDirectory(dir)) {
                System.err.println("dempano-spark: warning: the DEM folder " + dir + " is not on the driver ("
                        + hostName() + "): every row fails unless it is on every executor's node");
            }
            demDirs.add(dir.toString());
        }
        settings.demDirs = demDirs;
        // The viewpoint columns present, by their name in the table (matched as dempano batch matches them).
        Map<String, String> known = new LinkedHashMap<>();
        for (String c : table.columns()) {
            String n = c.trim().toLowerCase(Locale.ROOT);
            if (ViewpointCsv.COLUMNS.contains(n) && known.put(n, c) != null) {
                throw new IllegalArgumentException("the table names column '" + n + "' twice");
            }
        }
        for (String required : List.of(ViewpointCsv.ID, ViewpointCsv.LAT, ViewpointCsv.LON)) {
            if (!known.containsKey(required) && (required.equals(ViewpointCsv.ID) || !known.containsKey(ViewpointCsv.IMAGE))) {
                throw new IllegalArgumentException("the table has no column '" + required + "' (it has: "
                        + String.join(", ", table.columns()) + "; required: id, lat, lon; or id and image for photos)");
            }
        }
        List<Column> cells = new ArrayList<>();
        // Trimmed as the CSV reader trims (a Parquet id ' a' was rendered as 'a', over the files of another row 'a').
        known.forEach((n, c) -> cells.add(org.apache.spark.sql.functions.trim(col("`" + c + "`").cast(DataTypes.StringType)).as(n)));
        cells.add(java.util.Arrays.asList(table.columns()).contains(FIELDS_ERROR) ? col(FIELDS_ERROR)
                : lit(null).cast(DataTypes.StringType).as(FIELDS_ERROR));
        Dataset<Row> rows = table.select(cells.toArray(new Column[0])).withColumn(SEQ, monotonically_increasing_id());

        // Repeated ids (without regard to case, among safe ids), the first in table order kept, as dempano batch does.
        Column id = col(ViewpointCsv.ID);
        Column safe = id.rlike("^[A-Za-z0-9][A-Za-z0-9._-]*$").and(id.endsWith(".").unary_$bang()).and(length(id).leq(100));
        rows = rows.withColumn(KEY, when(safe, lower(id)).otherwise(concat(lit("\u0000"), col(SEQ).cast("string"))));
        var byId = Window.partitionBy(KEY).orderBy(SEQ);
        rows = rows.withColumn(DUP, when(row_number().over(byId).gt(1),
                concat(lit("row '"), first(id).over(byId), lit("'"))));

        // Ids whose files would be another's (a and a-distance both write a-distance.png): the later one in table order
        // is that row's error, as dempano batch has it (BatchIds.clashingIds).
        List<Column> written = new ArrayList<>();
        for (String suffix : dempano.batch.BatchIds.FILE_SUFFIXES) {
            written.add(concat(col(KEY), lit(suffix.toLowerCase(Locale.ROOT))));
        }
        var byName = Window.partitionBy(NAME).orderBy(CLASH_SEQ);
        Dataset<Row> clashes = rows.filter(safe.and(col(DUP).isNull()))
                .select(col(SEQ).as(CLASH_SEQ), id.as(CLASH_ID), explode(array(written.toArray(new Column[0]))).as(NAME))
                .withColumn(FIRST_ID, first(col(CLASH_ID)).over(byName))
                .withColumn(CLASH, row_number().over(byName))
                .filter(col(CLASH).gt(1))
                .groupBy(CLASH_SEQ).agg(min(concat(lit("id '"), col(CLASH_ID), lit("' would write "), col(NAME),
                        lit(", a file of id '"), col(FIRST_ID), lit("' (row '"), col(FIRST_ID),
                        lit("'): choose ids that are not another id with a file suffix"))).as(CLASH));
        rows = rows.join(clashes, rows.col(SEQ).equalTo(clashes.col(CLASH_SEQ)), "left_outer")
                .withColumn(FIELDS_ERROR, coalesce(col(FIELDS_ERROR), col(CLASH))).drop(CLASH_SEQ, CLASH);

        // Photo rows without lat/lon (the position in the photo's EXIF) sort first, together.
        rows = rows.withColumn(LAT, known.containsKey(ViewpointCsv.LAT) ? col(ViewpointCsv.LAT).cast(DataTypes.DoubleType)
                        : lit(null).cast(DataTypes.DoubleType))
                .withColumn(LON, known.containsKey(ViewpointCsv.LON) ? col(ViewpointCsv.LON).cast(DataTypes.DoubleType)
                        : lit(null).cast(DataTypes.DoubleType))
                .withColumn(TLAT, floor(col(LAT))).withColumn(TLON, floor(col(LON)));
        int n = Math.max(1, partitions);
        rows = switch (order) {
            case TILE -> rows.repartitionByRange(n, col(TLAT), col(TLON), col(LAT), col(LON))
                    .sortWithinPartitions(TLAT, TLON, LAT, LON);
            case RANDOM -> rows.withColumn(KEY, rand(seed)).repartitionByRange(n, col(KEY)).sortWithinPartitions(KEY);
            case INPUT -> rows.repartitionByRange(n, col(SEQ)).sortWithinPartitions(SEQ);
        };
        List<String> names = new ArrayList<>(known.keySet());
        JavaRDD<Row> out = rows.select(concatColumns(names)).javaRDD().mapPartitions(new RenderPartition(settings, names));
        StructType schema = new StructType()
                .add("id", DataTypes.StringType).add("status", DataTypes.StringType).add("files", DataTypes.StringType)
                .add("seconds", DataTypes.StringType).add("error", DataTypes.StringType);
        String resultsDir = resultsDir(settings.outDir);
        org.apache.hadoop.conf.Configuration conf = spark.sparkContext().hadoopConfiguration();
        org.apache.hadoop.fs.Path lock = claim(settings.outDir, conf);
        try {
            // Written beside the table of the job before, which is replaced only once this one is whole (a job killed
            // midway left no table at all: the write clears its folder first, and the rendering runs inside it).
            String writing = settings.outDir.replaceAll("/+$", "") + "/" + RESULTS_WRITING;
            spark.createDataFrame(out, schema).write().mode("overwrite").option("header", "true").option("escape", "\"")
                    .csv(writing);
            replace(writing, resultsDir, conf);
            Dataset<Row> results = spark.read().option("header", "true").option("escape", "\"").option("multiLine", "true")
                    .csv(resultsDir);
            long total = 0, ok = 0;
            for (Row r : results.groupBy("status").count().collectAsList()) {
                total += r.getLong(1);
                ok += "ok".equals(r.getString(0)) ? r.getLong(1) : 0;
            }
            return new Summary(total, ok, total - ok, (System.nanoTime() - t0) / 1e9, resultsDir);
        } finally {
            release(lock, conf);
        }
    }

    /** The output folder cannot be used: it is a file, cannot be made, or another job is writing into it. */
    public static final class OutputFolderException extends RuntimeException {
        private static final long serialVersionUID = 1L;

        OutputFolderException(String message, Throwable cause) {
            super(message, cause);
        }
    }

    /** The marker a job holds in its output folder while it runs. */
    public static final String LOCK_FILE = "_dempano_job_running";

    /**
     * Claims the output folder for this job: makes it, and creates {@link #LOCK_FILE} in it, failing where the file is
     * there already (another job writes into the folder: two jobs lost and mixed each other's results lines). The file
     * names the driver that holds it; a job killed before it could remove it leaves it behind, and the message says to
     * delete it then.
     */
    static org.apache.hadoop.fs.Path claim(String outDir, org.apache.hadoop.conf.Configuration conf) {
        org.apache.hadoop.fs.Path dir = new org.apache.hadoop.fs.Path(outDir);
        org.apache.hadoop.fs.Path lock = new org.apache.hadoop.fs.Path(dir, LOCK_FILE);
        org.apache.hadoop.fs.FileSystem fs;
        try {
            fs = dir.getFileSystem(conf);
            if (fs.exists(dir) && !fs.getFileStatus(dir).isDirectory()) {
                throw new OutputFolderException("the output folder " + outDir + " is a file: choose a folder", null);
            }
            fs.mkdirs(dir);
        } catch (java.io.IOException e) {
            throw new OutputFolderException("cannot make the output folder " + outDir + ": " + e.getMessage(), e);
        }
        String holder = java.lang.management.ManagementFactory.getRuntimeMXBean().getName() + " since "
                + java.time.Instant.now();
        try (org.apache.hadoop.fs.FSDataOutputStream o = fs.create(lock, false)) {
            o.write((holder + "\n").getBytes(java.nio.charset.StandardCharsets.UTF_8));
        } catch (org.apache.hadoop.fs.FileAlreadyExistsException e) {
            String other;
            try (java.io.InputStream in = fs.open(lock)) {
                other = new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8).strip();
            } catch (java.io.IOException e2) {
                other = "?";
            }
            throw new OutputFolderException("another job is writing into " + outDir + " (" + other + "; " + LOCK_FILE
                    + " there): wait for it to end or choose another output folder; if no job is running, delete "
                    + new org.apache.hadoop.fs.Path(dir, LOCK_FILE), e);
        } catch (java.io.IOException e) {
            throw new OutputFolderException("cannot write into the output folder " + outDir + ": " + e.getMessage(), e);
        }
        return lock;
    }

    private static void release(org.apache.hadoop.fs.Path lock, org.apache.hadoop.conf.Configuration conf) {
        try {
            lock.getFileSystem(conf).delete(lock, false);
        } catch (java.io.IOException e) {
            System.err.println("dempano-spark: could not remove " + lock + ": " + e.getMessage() + " (delete it before the next job)");
        }
    }

    /** The results table while the job writes it, in the output folder (Hadoop's readers skip names starting with _). */
    public static final String RESULTS_WRITING = "_results_writing";

    /** Puts the table just written in place of the one before. */
    private static void replace(String written, String resultsDir, org.apache.hadoop.conf.Configuration conf) {
        org.apache.hadoop.fs.Path from = new org.apache.hadoop.fs.Path(written), to = new org.apache.hadoop.fs.Path(resultsDir);
        try {
            org.apache.hadoop.fs.FileSystem fs = to.getFileSystem(conf);
            if (fs.exists(to) && !fs.delete(to, true)) {
                throw new java.io.IOException("cannot remove the table of the job before");
            }
            if (!fs.rename(from, to)) {
                throw new java.io.IOException("cannot rename " + from + " to " + to);
            }
        } catch (java.io.IOException e) {
            throw new OutputFolderException("the results table is in " + written + " but could not be put in place of "
                    + resultsDir + ": " + e.getMessage(), e);
        }
    }

    /**
     * The output folder as the driver means it: a relative path made absolute on the driver's file system (its default
     * one: the local disk, or HDFS where the cluster sets it), as Spark's own writers resolve it; a local path as a path.
     */
    static String qualified(SparkSession spark, String outDir) {
        if (Hadoop.isUri(outDir)) {
            return outDir; // a URI's path is absolute (scheme:/…)
        }
        org.apache.hadoop.fs.Path p = new org.apache.hadoop.fs.Path(outDir);
        try {
            org.apache.hadoop.fs.Path q = p.getFileSystem(spark.sparkContext().hadoopConfiguration()).makeQualified(p);
            return "file".equals(q.toUri().getScheme()) ? java.nio.file.Path.of(q.toUri()).toString() : q.toString();
        } catch (java.io.IOException | IllegalArgumentException e) {
            throw new OutputFolderException("cannot resolve the output folder " + outDir + ": " + e.getMessage(), e);
        }
    }

    /** This machine's name, for messages about what is on which node. */
    static String hostName() {
        try {
            return java.net.InetAddress.getLocalHost().getHostName();
        } catch (java.io.IOException e) {
            return "this host";
        }
    }

    /** Where the results table goes: {@code OUT/results}. */
    public static String resultsDir(String outDir) {
        return outDir.replaceAll("/+$", "") + "/results";
    }

    private static Column[] concatColumns(List<String> names) {
        List<Column> c = new ArrayList<>();
        for (String n : names) {
            c.add(col(n));
        }
        c.add(col(DUP));
        c.add(col(FIELDS_ERROR));
        return c.toArray(new Column[0]);
    }

    /** An executor's side: renders a partition's rows one after another, lazily, with the JVM's renderer. */
    static final class RenderPartition implements FlatMapFunction<Iterator<Row>, Row>, Serializable {
        private static final long serialVersionUID = 1L;
        private final JobSettings settings;
        private final List<String> names;

        RenderPartition(JobSettings settings, List<String> names) {
            this.settings = settings;
            this.names = List.copyOf(names);
        }

        @Override
        public Iterator<Row> call(Iterator<Row> in) {
            RowRenderer renderer = new RowRenderer(settings);
            return new Iterator<>() {
                @Override
                public boolean hasNext() {
                    return in.hasNext();
                }

                @Override
                public Row next() {
                    if (!in.hasNext()) {
                        throw new NoSuchElementException();
                    }
                    Row r = in.next();
                    Map<String, String> cells = new LinkedHashMap<>();
                    for (int i = 0; i < names.size(); i++) {
                        cells.put(names.get(i), r.getString(i));
                    }
                    String fieldsError = r.getString(names.size() + 1);
                    String id = cells.get(ViewpointCsv.ID);
                    RowRenderer.Outcome o = fieldsError != null
                            ? RowRenderer.Outcome.error(id == null ? "" : id, "row '" + (id == null ? "" : id) + "': " + fieldsError, 0)
                            : renderer.render(id, cells, r.getString(names.size()));
                    // Control characters (a line break in an id) as ?, as dempano batch writes results.csv.
                    return RowFactory.create(dempano.batch.BatchIds.printable(o.id()), o.status(), o.files(),
                            String.format(Locale.ROOT, "%.3f", o.seconds()), o.error());
                }
            };
        }
    }
}

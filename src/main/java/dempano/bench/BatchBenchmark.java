package dempano.bench;

import dempano.util.Quantiles;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVParser;
import org.apache.commons.csv.CSVRecord;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code gradle benchBatch}: seconds per panorama for N nearby viewpoints rendered by one
 * {@code dempano batch} process against one {@code dempano} process per viewpoint, and against one start
 * script per viewpoint handing it to the resident process ({@code DEMPANO_RESIDENT=on}; the round's first
 * run starts it, cold, and the round's end stops it), all through the installed start script (JVM start,
 * OpenGL context and cold caches included), in alternating rounds. Prints a Markdown table; writes nothing else (outputs go to a temporary folder, deleted).
 */
@Command(name = "bench-batch", mixinStandardHelpOptions = true,
        description = "Batch against one process per panorama, seconds per panorama.")
public final class BatchBenchmark implements Callable<Integer> {
    @Option(names = "--dempano", description = "The installed start script (default: ${DEFAULT-VALUE}).",
            defaultValue = "build/install/dempano/bin/dempano")
    Path dempano;
    @Option(names = "--dem-dir", description = "DEM folder (default: ${DEFAULT-VALUE}).", defaultValue = "../shared/dem")
    Path demDir;
    @Option(names = "--lat", description = "Centre, degrees north (default: ${DEFAULT-VALUE}, Mount Washington).", defaultValue = "44.2706")
    double latDeg;
    @Option(names = "--lon", description = "Centre, degrees east (default: ${DEFAULT-VALUE}).", defaultValue = "-71.3033")
    double lonDeg;
    @Option(names = "--viewpoints", description = "Viewpoints, on a grid about 3 km apart (default: ${DEFAULT-VALUE}).", defaultValue = "20")
    int viewpoints;
    @Option(names = "--rounds", description = "Alternating rounds of batch and single processes (default: ${DEFAULT-VALUE}).", defaultValue = "2")
    int rounds;
    @Option(names = "--settings", description = "Options for every panorama (default: ${DEFAULT-VALUE}).",
            defaultValue = "--ppd 20 --range-km 100 --elevation-range -10:5")
    String settings;

    public static void main(String[] args) {
        System.exit(ReportTool.run(new BatchBenchmark(), args));
    }

    /** The grid: 5 columns, 0.03° of latitude (3.3 km) and 0.04° of longitude (3.2 km at 44° N) apart, centred. */
    static List<double[]> grid(double lat, double lon, int n) {
        List<double[]> out = new ArrayList<>();
        int cols = 5, rows = (n + cols - 1) / cols;
        for (int i = 0; i < n; i++) {
            int r = i / cols, c = i % cols;
            out.add(new double[] {lat + 0.03 * (r - (rows - 1) / 2.0), lon + 0.04 * (c - (cols - 1) / 2.0)});
        }
        return out;
    }

    @Override
    public Integer call() throws Exception {
        if (!Files.isExecutable(dempano)) {
            System.err.println("bench-batch: " + dempano + " is missing: run gradle installDist first");
            return 1;
        }
        if (rounds < 1 || viewpoints < 2) { // (rows 2–N: at least two viewpoints)
            throw new IllegalArgumentException("--rounds must be at least 1 and --viewpoints at least 2, got " + rounds
                    + " and " + viewpoints);
        }
        Path tmp = Files.createTempDirectory("dempano-bench-batch");
        try {
            return measure(tmp);
        } catch (IOException | InterruptedException | RuntimeException e) {
            // Its resident process too, if a failure left it running: it would hold a GB for 10 minutes.
            if (Files.exists(tmp.resolve("resident"))) {
                try {
                    run(List.of(dempano.toString(), "resident", "stop"), tmp, Map.of("DEMPANO_RESIDENT", "on",
                            "DEMPANO_RESIDENT_DIR", tmp.resolve("resident").toString()));
                } catch (IOException stop) {
                    e.addSuppressed(stop);
                }
            }
            throw e;
        } finally {
            deleteTree(tmp);
        }
    }

    private int measure(Path tmp) throws IOException, InterruptedException {
        List<double[]> at = grid(latDeg, lonDeg, viewpoints);
        StringBuilder csv = new StringBuilder("id,lat,lon\n");
        for (int i = 0; i < at.size(); i++) {
            csv.append(String.format(Locale.ROOT, "v%02d,%.5f,%.5f%n", i, at.get(i)[0], at.get(i)[1]));
        }
        Path csvFile = Files.writeString(tmp.resolve("viewpoints.csv"), csv);
        List<String> common = List.of(settings.trim().split("\\s+"));
        double[] batchWhole = new double[rounds], batchRowMean = new double[rounds], batchRowWarmMedian = new double[rounds];
        double[] singleMean = new double[rounds], singleMedian = new double[rounds];
        double[] residentMean = new double[rounds], residentMedian = new double[rounds];
        for (int round = 0; round < rounds; round++) {
            Path out = Files.createDirectories(tmp.resolve("batch" + round));
            List<String> cmd = new ArrayList<>(List.of(dempano.toString(), "batch", csvFile.toString(), "--out-dir", out.toString(),
                    "--dem-dir", demDir.toString()));
            cmd.addAll(common);
            batchWhole[round] = run(cmd, tmp) / viewpoints;
            double[] rows = rowSeconds(out.resolve("results.csv"));
            batchRowMean[round] = Arrays.stream(rows).average().orElse(Double.NaN);
            batchRowWarmMedian[round] = Quantiles.median(Arrays.copyOfRange(rows, 1, rows.length));
            System.err.printf(Locale.ROOT, "bench-batch: round %d batch: %.2f s per panorama (whole process / %d)%n",
                    round + 1, batchWhole[round], viewpoints);
            for (boolean resident : new boolean[] {false, true}) {
                // One start script per panorama: each in its own process, or (DEMPANO_RESIDENT=on) handed to the
                // resident process, which the round's first run starts and its end stops.
                Map<String, String> env = resident ? Map.of("DEMPANO_RESIDENT", "on", "DEMPANO_RESIDENT_DIR",
                        tmp.resolve("resident").toString()) : Map.of();
                double[] single = new double[viewpoints];
                for (int i = 0; i < viewpoints; i++) {
                    List<String> one = new ArrayList<>(List.of(dempano.toString(), "--lat", String.format(Locale.ROOT, "%.5f", at.get(i)[0]),
                            "--lon", String.format(Locale.ROOT, "%.5f", at.get(i)[1]), "--dem-dir", demDir.toString(),
                            "--out", tmp.resolve((resident ? "resident" : "single") + round + "-" + i).toString()));
                    one.addAll(common);
                    single[i] = run(one, tmp, env);
                }
                if (resident) {
                    run(List.of(dempano.toString(), "resident", "stop"), tmp, env);
                }
                (resident ? residentMean : singleMean)[round] = Arrays.stream(single).average().orElse(Double.NaN);
                (resident ? residentMedian : singleMedian)[round] = Quantiles.median(single);
                System.err.printf(Locale.ROOT, "bench-batch: round %d %s: %.2f s per panorama (mean of %d processes)%n",
                        round + 1, resident ? "resident" : "single", (resident ? residentMean : singleMean)[round], viewpoints);
            }
        }
        System.out.printf(Locale.ROOT, "%d viewpoints about 3 km apart around %.4f, %.4f; %s; PNG + distance written; "
                + "%d alternating rounds, median of rounds; patch deviations kept on disk in the run's own folder, "
                + "filled by its first process%n%n", viewpoints, latDeg, lonDeg, settings, rounds);
        System.out.println("| way | seconds per panorama |");
        System.out.println("|---|---:|");
        System.out.printf(Locale.ROOT, "| one process per panorama (installed start script), mean | %.2f |%n", Quantiles.median(singleMean));
        System.out.printf(Locale.ROOT, "| one process per panorama, median | %.2f |%n", Quantiles.median(singleMedian));
        System.out.printf(Locale.ROOT, "| one start script per panorama, DEMPANO_RESIDENT=on (the first starts it), mean | %.2f |%n",
                Quantiles.median(residentMean));
        System.out.printf(Locale.ROOT, "| one start script per panorama, DEMPANO_RESIDENT=on, median | %.2f |%n", Quantiles.median(residentMedian));
        System.out.printf(Locale.ROOT, "| `dempano batch`, whole process / %d | %.2f |%n", viewpoints, Quantiles.median(batchWhole));
        System.out.printf(Locale.ROOT, "| `dempano batch`, rows' own time, mean (cold first row included) | %.2f |%n", Quantiles.median(batchRowMean));
        System.out.printf(Locale.ROOT, "| `dempano batch`, rows 2–%d, median | %.2f |%n", viewpoints, Quantiles.median(batchRowWarmMedian));
        return 0;
    }

    /** Runs a command to its end (output discarded), seconds of wall-clock time; fails on a non-zero exit. */
    private static double run(List<String> cmd, Path dir) throws IOException, InterruptedException {
        return run(cmd, dir, Map.of());
    }

    /** As above, with these environment variables set. */
    private static double run(List<String> cmd, Path dir, Map<String, String> env) throws IOException, InterruptedException {
        long t = System.nanoTime();
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(dir.resolve("log.txt").toFile());
        // The patch deviations every process keeps on disk (DeviationStore) in this run's own folder, filled by its first
        // process: the figures do not depend on what the user's cache held before.
        pb.environment().put("DEMPANO_CACHE_DIR", dir.resolve("cache").toString());
        pb.environment().remove("DEMPANO_RESIDENT");
        pb.environment().putAll(env);
        Process p = pb.start();
        if (!p.waitFor(30, TimeUnit.MINUTES) || p.exitValue() != 0) {
            throw new IOException(String.join(" ", cmd) + " failed: " + Files.readString(dir.resolve("log.txt")));
        }
        return (System.nanoTime() - t) / 1e9;
    }

    private static double[] rowSeconds(Path results) throws IOException {
        try (CSVParser p = CSVParser.parse(Files.readString(results, StandardCharsets.UTF_8),
                CSVFormat.DEFAULT.builder().setHeader().setSkipHeaderRecord(true).get())) {
            return p.getRecords().stream().mapToDouble((CSVRecord r) -> Double.parseDouble(r.get("seconds"))).toArray();
        }
    }

    private static void deleteTree(Path dir) throws IOException {
        try (var s = Files.walk(dir)) {
            s.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        }
    }
}

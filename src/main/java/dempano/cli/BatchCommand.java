package dempano.cli;

import dempano.terrain.DeviationStore;
import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.batch.BatchIds;
import dempano.batch.BatchListener;
import dempano.batch.BatchRenderer;
import dempano.batch.BatchResult;
import dempano.batch.BatchRow;
import dempano.batch.BatchRun;
import dempano.batch.BatchSummary;
import dempano.batch.ViewpointCsv;
import dempano.batch.ViewpointCsvException;
import dempano.dem.DemSource;
import dempano.dem.PriorityDem;
import dempano.io.IoMessages;
import dempano.io.PanoramaWriter;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.text.DecimalFormat;
import java.time.Duration;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import me.tongfei.progressbar.ConsoleProgressBarConsumer;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import me.tongfei.progressbar.ProgressBarStyle;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code dempano batch VIEWPOINTS.csv --out-dir D}: every viewpoint of a CSV rendered in one process
 * (see {@link BatchRenderer}, {@link ViewpointCsv} for the columns). The options are the main
 * command's, as defaults for every row.
 */
@Command(name = "batch", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Renders the panorama of every viewpoint in a CSV file in one process (tiles, patch deviations and "
                + "meshes are reused from row to row).",
                "CSV columns (header line, any order, case-insensitive): id, lat, lon (required); altitude_m, offset_m, "
                        + "eye_height_m, range_km, ppd (optional: an empty cell takes the option's value). Other columns are ignored.",
                "Ids: letters, digits, '.', '_', '-' (no paths), unique without regard to case."},
        footer = {"", "Writes D/<id>.png, D/<id>-distance.npy, D/<id>-distance.png, D/<id>.json per row (each row's files as one "
                + "set: complete or absent) and D/results.csv (id,status,files,seconds,error; a line per row as it finishes).",
                "A bad row (bad number, coordinate out of range, missing tile, unsafe or repeated id) is reported and the rest go on.",
                "Ctrl-C stops after the row in progress: its files are complete and it is in results.csv.",
                "Exit codes: 0 every row done, 3 some rows failed (see results.csv), 1 unusable input (viewpoint file, "
                        + "header, DEM folder, output folder, OpenGL), 2 bad arguments, 130 interrupted."})
public final class BatchCommand implements Callable<Integer> {
    /** Exit code when some rows failed and the others were done. */
    public static final int EXIT_SOME_ROWS_FAILED = 3;
    /** Exit code when the batch was interrupted (Ctrl-C) after the row in progress. */
    public static final int EXIT_INTERRUPTED = 130;
    /** How long Ctrl-C waits for the row in progress to finish before the process ends anyway. */
    static final Duration INTERRUPT_GRACE = Duration.ofSeconds(60);

    @Parameters(index = "0", paramLabel = "VIEWPOINTS.csv", description = "Viewpoints, one per row (UTF-8 CSV with a header line; lines starting with # are comments; - reads standard input).")
    Path viewpoints;
    @Option(names = "--out-dir", required = true, paramLabel = "D", description = "Output folder (created if missing).")
    Path outDir;
    @Option(names = "--dem-dir", required = true, paramLabel = "DIR", description = "Directory of DEM tiles (.hgt, GeoTIFF); "
            + "repeatable, in priority order, as for a single panorama.")
    List<Path> demDirs;
    /** The main command's panorama options: every row's defaults (its columns override ppd, range, offset, eye height). */
    @picocli.CommandLine.Mixin
    PanoramaOptions panorama = new PanoramaOptions();
    @Option(names = "--progress", description = "Show the progress bar even when the terminal is not detected (it is shown on a terminal anyway).")
    boolean progress;

    /**
     * Which of the batch's files the viewpoints file is (the results, or a row's output), or null when none: the
     * batch would overwrite its own input.
     */
    static String writtenOver(Path viewpoints, Path outDir, List<BatchRow> rows) {
        Path file;
        try {
            file = viewpoints.toRealPath(); // the file itself: a link to results.csv is results.csv
            Path dir = file.getParent();
            if (dir == null || !Files.isSameFile(dir, outDir)) {
                return null;
            }
        } catch (IOException e) {
            return null; // the folder does not exist yet: nothing in it is overwritten
        }
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (name.equals(BatchRenderer.resultsFile(outDir).getFileName().toString().toLowerCase(Locale.ROOT))) {
            return "the results file";
        }
        for (BatchRow row : rows) {
            for (String suffix : dempano.batch.BatchIds.FILE_SUFFIXES) {
                if (row.valid() && name.equals((row.id() + suffix).toLowerCase(Locale.ROOT))) {
                    return "an output of row '" + row.id() + "'";
                }
            }
        }
        return null;
    }

    @Override
    public Integer call() throws Exception {
        PrintStream err = System.err;
        PanoramaRequest defaults = defaults();
        boolean reference = panorama.referenceRenderer();
        dempano.dem.DemFill fill = panorama.demFill(); // a bad --void-fill or --dem-blend: exit 2 before the CSV is read
        ViewpointCsv.Parsed parsed;
        try {
            parsed = ViewpointCsv.read(viewpoints, defaults);
        } catch (ViewpointCsvException e) {
            err.println("dempano batch: " + e.getMessage());
            return 1;
        }
        if (!parsed.ignoredColumns().isEmpty()) {
            err.println("dempano batch: ignoring columns " + String.join(", ", parsed.ignoredColumns()) + " (read: "
                    + String.join(", ", ViewpointCsv.COLUMNS) + ")");
        }
        // A missing DEM folder: exit 1 before anything is created.
        DemSource dem = PriorityDem.open(demDirs, fill, w -> err.println("  warning: " + w));
        try {
            Files.createDirectories(outDir);
        } catch (IOException e) {
            err.println("dempano batch: cannot create the output folder " + outDir + ": " + IoMessages.reason(e));
            return 1;
        }
        List<BatchRow> rows = parsed.rows();
        String overwritten = writtenOver(viewpoints, outDir, rows);
        if (overwritten != null) {
            err.println("dempano batch: cannot read and write " + viewpoints + ": it is " + overwritten
                    + ", which the batch writes; move it or choose another --out-dir");
            return 1;
        }
        err.printf(Locale.ROOT, "dempano batch: %d rows (%d valid) from %s, DEM %s, into %s%n", rows.size(),
                parsed.validCount(), viewpoints, dem.describe(), outDir);
        boolean terminal = StderrTerminal.isInteractive();
        boolean bar = progress || terminal;
        BatchSummary summary;
        java.util.concurrent.CountDownLatch reported = new java.util.concurrent.CountDownLatch(1);
        try (PanoramaRenderer r = reference ? PanoramaRenderer.openReference(dem)
                : PanoramaRenderer.openInBackground(dem).withDeviationStore(DeviationStore.userDefault())) {
            BatchRun run = new BatchRenderer(r, outDir, new PanoramaWriter.Options(panorama.pfm, null,
                    dempano.io.SummitWriter.LabelOptions.DEFAULT)).newRun(rows, bar ? new Bar(err, terminal) : new Log(err));
            Thread hook = new Thread(() -> interrupted(run, reported, err), "dempano-batch-interrupt");
            Runtime.getRuntime().addShutdownHook(hook);
            // The exit cleanup of uncommitted output sets waits for the row in progress, which Ctrl-C lets finish.
            Runnable finishing = () -> {
                try {
                    run.awaitFinished(INTERRUPT_GRACE.plusSeconds(5));
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            };
            dempano.io.OutputSet.finishBeforeCleanup(finishing);
            try {
                summary = run.run();
            } catch (IOException e) { // results.csv: a read-only folder, another batch writing into it
                err.println("dempano batch: " + e.getMessage());
                return 1;
            } finally {
                dempano.io.OutputSet.noLongerFinishing(finishing);
                try {
                    Runtime.getRuntime().removeShutdownHook(hook);
                } catch (IllegalStateException e) {
                    // shutting down: the hook is running
                }
            }
        }
        err.printf(Locale.ROOT, "dempano batch: %d ok, %d failed, %d not run of %d rows in %.1f s (%s s per panorama); "
                        + "results in %s%n", summary.okCount(), summary.errorCount(), summary.notRun(), summary.rows(),
                summary.seconds(), Double.isNaN(summary.secondsPerPanorama()) ? "-"
                        : String.format(Locale.ROOT, "%.2f", summary.secondsPerPanorama()), BatchRenderer.resultsFile(outDir));
        reported.countDown();
        if (summary.fatal() != null) {
            err.println("dempano batch: stopped: " + summary.fatal());
            return 1;
        }
        if (summary.cancelled()) {
            return EXIT_INTERRUPTED;
        }
        return summary.allOk() ? 0 : EXIT_SOME_ROWS_FAILED;
    }

    /** Ctrl-C: the row in progress finishes (files and results line), then the process ends. */
    private static void interrupted(BatchRun run, java.util.concurrent.CountDownLatch reported, PrintStream err) {
        run.cancel();
        try {
            if (run.awaitFinished(Duration.ZERO)) {
                return;
            }
            err.println();
            err.println("dempano batch: interrupted: finishing the row in progress (up to " + INTERRUPT_GRACE.toSeconds() + " s)");
            if (!run.awaitFinished(INTERRUPT_GRACE)) {
                err.println("dempano batch: the row in progress did not finish; its files are not in place");
                return;
            }
            reported.await(2, java.util.concurrent.TimeUnit.SECONDS); // the summary line
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** The request every row starts from: the options (checked here at (0, 0): a bad option is a bad argument, exit 2, before any row is read). */
    PanoramaRequest defaults() {
        return panorama.applyTo(PanoramaRequest.at(0, 0), PanoramaRequest.DEFAULT_RANGE_METRES);
    }

    /** One line per row (for logs and pipes). */
    static final class Log implements BatchListener {
        private final PrintStream err;
        private int total;

        Log(PrintStream err) {
            this.err = err;
        }

        @Override
        public void started(int rows) {
            total = rows;
        }

        @Override
        public void rowFinished(BatchResult r, int index) {
            err.println(line(r, index, total));
        }
    }

    /** A row's line; its id as results.csv writes it (a control character in a refused id as ?: one line, no escapes). */
    static String line(BatchResult r, int index, int total) {
        String id = BatchIds.printable(r.id());
        return r.ok()
                ? String.format(Locale.ROOT, "dempano batch: [%d/%d] %s ok, %.2f s, %d files", index + 1, total, id,
                r.seconds(), r.files().size())
                : String.format(Locale.ROOT, "dempano batch: [%d/%d] %s error: %s", index + 1, total, id, r.error());
    }

    /**
     * A progress bar with rate and ETA; bad rows get a line of their own above it. Its width is the terminal's, asked
     * of stderr itself ({@link StderrTerminal}): the library's own console consumer opens a JLine terminal for that,
     * which takes over SIGINT, and Ctrl-C then killed the batch outright (no row finished, no summary, staging
     * folders and unlisted sets left).
     */
    static final class Bar implements BatchListener {
        private final PrintStream err;
        private final boolean terminal;
        private ProgressBar bar;
        private int total;

        /** @param terminal whether stderr is a terminal (else the bar is asked for: lines end in a return only) */
        Bar(PrintStream err, boolean terminal) {
            this.err = err;
            this.terminal = terminal;
        }

        @Override
        public void started(int rows) {
            total = rows;
            bar = new ProgressBarBuilder().setTaskName("batch").setInitialMax(rows).setStyle(ProgressBarStyle.ASCII)
                    .setUnit(" pano", 1).showSpeed(new DecimalFormat("0.00")).setUpdateIntervalMillis(500)
                    .setConsumer(consumer(err, terminal)).build();
        }

        /** The bar's output: lines as wide as stderr's terminal (else {@link StderrTerminal#DEFAULT_COLUMNS}), less one. */
        static ConsoleProgressBarConsumer consumer(PrintStream err, boolean terminal) {
            return new ConsoleProgressBarConsumer(err, StderrTerminal.DEFAULT_COLUMNS - 1) {
                @Override
                public int getMaxRenderedLength() {
                    return (terminal ? StderrTerminal.columns() : StderrTerminal.DEFAULT_COLUMNS) - 1;
                }
            };
        }

        @Override
        public void rowStarted(BatchRow row, int index) {
            bar.setExtraMessage(" " + BatchIds.printable(row.id())); // after the rate: "0.50 pano/s p7"
        }

        @Override
        public void rowFinished(BatchResult r, int index) {
            if (!r.ok()) {
                synchronized (err) {
                    err.print(terminal ? "\r\033[2K" : "\n"); // off the bar's line
                    err.println(line(r, index, total));
                }
            }
            bar.step();
        }

        @Override
        public void finished(BatchSummary summary) {
            bar.close();
        }
    }
}

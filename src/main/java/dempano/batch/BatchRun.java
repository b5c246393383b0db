package dempano.batch;

import dempano.PanoramaRenderer;
import dempano.io.IoMessages;
import dempano.io.OutputSet;
import dempano.photo.PhotoJob;
import dempano.io.PanoramaWriter;
import dempano.panorama.Panorama;
import dempano.render.GlUnavailableException;
import dempano.render.RenderFailedException;
import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * One pass over a batch's rows (made by {@link BatchRenderer#newRun}). {@link #run()} renders the
 * rows in order on the calling thread; each row's files are written as one {@link OutputSet}
 * (staged in a hidden folder, renamed into place on commit), so a row's files are either all there,
 * new, or not there at all. A row that fails (bad values, missing tiles, no DEM data at the
 * viewpoint, not enough memory, an unwritable file) is recorded as an error and the next row
 * starts; only a failure of the renderer itself (no OpenGL, the GL thread dying) stops the batch.
 *
 * <p>{@link #cancel()}, from any thread (a shutdown hook on Ctrl-C), lets the row in progress (and the
 * row being written, see {@link #run()}) finish and commit its files, records them, and starts no further row. {@link #awaitFinished} waits for
 * that. Rows not reached are not in the results.
 */
public final class BatchRun {
    private final PanoramaRenderer renderer;
    private final Path outDir;
    private final PanoramaWriter.Options writing;
    private final List<BatchRow> rows;
    private final BatchListener listener;
    private final AtomicBoolean cancelled = new AtomicBoolean();
    private final AtomicBoolean started = new AtomicBoolean();
    private final CountDownLatch finished = new CountDownLatch(1);

    BatchRun(PanoramaRenderer renderer, Path outDir, PanoramaWriter.Options writing, List<BatchRow> rows,
             BatchListener listener) {
        this.renderer = renderer;
        this.outDir = outDir;
        this.writing = writing;
        this.rows = List.copyOf(rows);
        this.listener = listener;
    }

    /** Stops the run after the row in progress (its files complete, its result recorded); no-op once finished. */
    public void cancel() {
        cancelled.set(true);
    }

    /** Whether {@link #cancel()} was called. */
    public boolean isCancelled() {
        return cancelled.get();
    }

    /**
     * Waits until {@link #run()} has returned or thrown (at once when it never started).
     *
     * @return false when the time ran out first
     */
    public boolean awaitFinished(Duration timeout) throws InterruptedException {
        return !started.get() || finished.await(timeout.toMillis(), TimeUnit.MILLISECONDS);
    }

    /**
     * Renders the rows in order, writing {@code results.csv} line by line. A panorama row's files are written on a
     * second thread while the next row renders (at most one row is being written, so at most two panoramas are in
     * memory); its line goes to {@code results.csv}, and {@link BatchListener#rowFinished} is told, on the writer thread
     * as soon as its files are in place, before the next row's. Its seconds are those of its own work: rendering, then writing (not the time
     * its writing waited for, or overlapped, the next row's rendering).
     *
     * @return the summary; {@link BatchSummary#fatal()} is set when the renderer failed and the rest was skipped
     * @throws IOException when {@code results.csv} cannot be created or written (the output folder is
     *                     missing or read-only): the message names the file
     * @throws IllegalStateException when called a second time
     */
    public BatchSummary run() throws IOException {
        if (!started.compareAndSet(false, true)) {
            throw new IllegalStateException("a batch run runs once");
        }
        long t0 = System.nanoTime();
        List<BatchResult> results = new ArrayList<>();
        String fatal = null;
        Path resultsFile = BatchRenderer.resultsFile(outDir);
        java.util.concurrent.ExecutorService writer = java.util.concurrent.Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "dempano-batch-writer");
            t.setDaemon(true);
            return t;
        });
        Writing pending = null;
        try (ResultsCsv csv = create(resultsFile)) {
            tell(() -> listener.started(rows.size()));
            Map<String, String> seen = new HashMap<>(); // collision key → where the id was first
            for (int i = 0; i < rows.size() && !cancelled.get(); i++) {
                BatchRow row = rows.get(i);
                int index = i;
                tell(() -> listener.rowStarted(row, index));
                long start = System.nanoTime();
                BatchResult result = null;
                Rendered rendered = null;
                String idProblem = BatchIds.problem(row.id());
                String first = idProblem == null ? seen.putIfAbsent(BatchIds.collisionKey(row.id()), row.where()) : null;
                String clash = idProblem == null && first == null ? clash(row, seen) : null;
                if (!row.valid()) {
                    result = BatchResult.error(row, row.error(), 0);
                } else if (idProblem != null) {
                    result = BatchResult.error(row, prefixed(row, idProblem), 0);
                } else if (first != null) {
                    result = BatchResult.error(row, prefixed(row, "duplicate id '" + row.id() + "' (first at " + first + ")"), 0);
                } else if (clash != null) {
                    result = BatchResult.error(row, prefixed(row, clash), 0);
                } else {
                    try {
                        if (row.photo() != null) {
                            result = BatchResult.ok(row, renderPhoto(row), seconds(start));
                        } else {
                            rendered = render(row);
                        }
                    } catch (RenderFailedException | GlUnavailableException e) {
                        fatal = message(e);
                        result = BatchResult.error(row, prefixed(row, fatal), seconds(start));
                    } catch (IOException | RuntimeException | OutOfMemoryError e) {
                        result = failed(row, e, seconds(start));
                    }
                }
                double renderSeconds = seconds(start);
                // The row before must be in place, and recorded, before this one is recorded or written.
                Writing before = pending;
                pending = null;
                try {
                    finish(before);
                } catch (IOException | RuntimeException | Error e) {
                    if (rendered != null) {
                        discard(rendered, e); // results.csv cannot be written: this row is not written either
                    }
                    throw e;
                }
                if (rendered != null) {
                    // Its line is written by the writer as soon as its files are in place (not after the next row has
                    // rendered: a batch killed meanwhile lost the line of a complete set).
                    Rendered toWrite = rendered;
                    pending = new Writing(writer.submit(() -> {
                        long began = System.nanoTime();
                        BatchResult written;
                        try {
                            written = BatchResult.ok(row, write(toWrite), renderSeconds + seconds(began));
                        } catch (IOException | RuntimeException | OutOfMemoryError e) {
                            written = failed(row, e, renderSeconds); // its writing's seconds are not known
                        }
                        record(written, index, csv, results, resultsFile);
                        return null;
                    }));
                    continue;
                }
                record(result, index, csv, results, resultsFile);
                if (fatal != null) {
                    break;
                }
            }
            finish(pending);
            pending = null;
        } finally {
            if (pending != null) { // results.csv failed: still never leave with a set half written
                try {
                    pending.recorded().get();
                } catch (Exception e) {
                    // its failure is not recorded: results.csv could not be written
                }
            }
            writer.shutdown();
            finished.countDown();
        }
        BatchSummary summary = new BatchSummary(results, rows.size(), cancelled.get() && results.size() < rows.size(),
                fatal, seconds(t0));
        tell(() -> listener.finished(summary));
        return summary;
    }

    /** A panorama row being written, and then recorded, on the writer thread. */
    private record Writing(java.util.concurrent.Future<Void> recorded) {
    }

    /** A rendered panorama and its set, opened before rendering. */
    private record Rendered(OutputSet set, Panorama panorama) {
    }

    /**
     * Waits until a row being written (null: none) is in place and recorded; rethrows what stopped its recording
     * (results.csv unwritable) or its writing (an Error but running out of memory).
     */
    private static void finish(Writing w) throws IOException {
        if (w == null) {
            return;
        }
        try {
            dempano.util.Threads.getUninterruptibly(w.recorded()); // the files are being written: wait for them all the same
        } catch (java.util.concurrent.ExecutionException e) {
            if (e.getCause() instanceof IOException io) {
                throw io;
            }
            throw dempano.util.Threads.unchecked(e.getCause());
        }
    }

    /**
     * Adds a row's result, its line in results.csv and tells the listener. Called on the run's thread or the writer's,
     * never at once (a row's writing is waited for before the next is recorded), in row order.
     */
    private void record(BatchResult result, int index, ResultsCsv csv, List<BatchResult> results, Path resultsFile)
            throws IOException {
        results.add(result);
        try {
            csv.append(result);
        } catch (IOException e) {
            throw new IOException("cannot write " + resultsFile + ": " + IoMessages.reason(e), e);
        }
        tell(() -> listener.rowFinished(result, index));
    }

    /** A row's failure as its result line. */
    private static BatchResult failed(BatchRow row, Throwable e, double seconds) {
        if (e instanceof OutOfMemoryError) {
            return BatchResult.error(row, prefixed(row, "out of memory (" + e.getMessage()
                    + "): lower ppd or range, or give Java more memory (DEMPANO_OPTS=-Xmx…)"), seconds);
        }
        if (e instanceof IOException io) {
            return BatchResult.error(row, prefixed(row, IoMessages.reason(io)), seconds);
        }
        if (e instanceof RuntimeException) {
            return BatchResult.error(row, prefixed(row, message(e)), seconds);
        }
        if (e instanceof Error err) {
            throw err;
        }
        return BatchResult.error(row, prefixed(row, message(e)), seconds);
    }

    private static ResultsCsv create(Path file) throws IOException {
        try {
            return ResultsCsv.create(file);
        } catch (BatchFolderInUseException e) {
            throw e;
        } catch (IOException e) {
            throw new IOException("cannot write " + file + ": " + IoMessages.reason(e), e);
        }
    }

    /** Orients and renders a photo row and puts its files in place (see {@link PhotoJob}). */
    private List<Path> renderPhoto(BatchRow row) throws IOException {
        BatchPhoto photo = row.photo();
        return PhotoJob.run(renderer, new PhotoJob.Input(photo.image(), photo.overrides(), null, null, photo.ranges(),
                row.request(), null, outDir.resolve(row.id()).toString()), PhotoJob.Log.NONE).files();
    }

    /**
     * Why a row's files would share names with an earlier row's ({@link BatchIds#clashingIds}: ids {@code a} and
     * {@code a-distance} both write {@code a-distance.png}); null when they would not.
     */
    private static String clash(BatchRow row, Map<String, String> seen) {
        for (Map.Entry<String, String> c : BatchIds.clashingIds(row.id()).entrySet()) {
            String where = seen.get(c.getKey());
            if (where != null) {
                return "id '" + row.id() + "' would write " + c.getValue() + ", a file of id '" + c.getKey() + "' (" + where
                        + "): choose ids that are not another id with a file suffix";
            }
        }
        return null;
    }

    /** Renders a panorama row into a set opened first (an unwritable destination is found before rendering). */
    private Rendered render(BatchRow row) throws IOException {
        OutputSet set = OutputSet.open(outDir.resolve(row.id()).toString());
        try {
            set.checkTargets(PanoramaWriter.suffixes(row.request().colour(), row.request().distance(),
                    row.request().layers(), writing));
            return new Rendered(set, renderer.render(row.request()));
        } catch (IOException | RuntimeException | Error e) {
            set.close(); // discards the uncommitted set
            throw e;
        }
    }

    /** Closes (discards) a rendered row's uncommitted set, a failure to do so added to {@code cause}. */
    private static void discard(Rendered r, Throwable cause) {
        try {
            r.set().close();
        } catch (RuntimeException e) {
            cause.addSuppressed(e);
        }
    }

    /** Writes a rendered row's files and puts them in place as one set; after a failure none of its new files is there. */
    private List<Path> write(Rendered r) throws IOException {
        try (OutputSet set = r.set()) {
            List<Path> files = PanoramaWriter.stage(set, r.panorama(), writing);
            set.commit();
            return files;
        }
    }

    private static String prefixed(BatchRow row, String message) {
        String where = row.where() + ": ";
        return message.startsWith(where) ? message : where + message;
    }

    private static String message(Throwable e) {
        return e.getMessage() == null || e.getMessage().isBlank() ? e.toString() : e.getMessage();
    }

    private static double seconds(long sinceNanos) {
        return (System.nanoTime() - sinceNanos) / 1e9;
    }

    /** Calls the listener: one call at a time (the writer thread tells of rows too); its failure is not the batch's. */
    private void tell(Runnable r) {
        synchronized (listener) {
            try {
                r.run();
            } catch (RuntimeException | Error e) {
                // a listener's failure is not the batch's (an AssertionError in a test's listener stopped the batch)
            }
        }
    }
}

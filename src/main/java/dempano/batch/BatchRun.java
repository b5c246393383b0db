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
 * <p>{@link #cancel()}, from any thread (a shutdown hook on Ctrl-C), lets the row in progress finish
 * and commit its files, records it, and starts no further row. {@link #awaitFinished} waits for
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
     * Renders the rows in order, writing {@code results.csv} line by line.
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
        try (ResultsCsv csv = create(resultsFile)) {
            quietly(() -> listener.started(rows.size()));
            Map<String, String> seen = new HashMap<>(); // collision key → where the id was first
            for (int i = 0; i < rows.size() && !cancelled.get(); i++) {
                BatchRow row = rows.get(i);
                int index = i;
                quietly(() -> listener.rowStarted(row, index));
                long start = System.nanoTime();
                BatchResult result;
                String idProblem = BatchIds.problem(row.id());
                String first = idProblem == null ? seen.putIfAbsent(BatchIds.collisionKey(row.id()), row.where()) : null;
                if (!row.valid()) {
                    result = BatchResult.error(row, row.error(), 0);
                } else if (idProblem != null) {
                    result = BatchResult.error(row, prefixed(row, idProblem), 0);
                } else if (first != null) {
                    result = BatchResult.error(row, prefixed(row, "duplicate id '" + row.id() + "' (first at " + first + ")"), 0);
                } else {
                    try {
                        List<Path> files = renderOne(row);
                        result = BatchResult.ok(row, files, seconds(start));
                    } catch (RenderFailedException | GlUnavailableException e) {
                        fatal = message(e);
                        result = BatchResult.error(row, prefixed(row, fatal), seconds(start));
                    } catch (OutOfMemoryError e) {
                        result = BatchResult.error(row, prefixed(row, "out of memory (" + e.getMessage()
                                + "): lower ppd or range, or give Java more memory (DEMPANO_OPTS=-Xmx…)"), seconds(start));
                    } catch (IOException e) {
                        result = BatchResult.error(row, prefixed(row, IoMessages.reason(e)), seconds(start));
                    } catch (RuntimeException e) {
                        result = BatchResult.error(row, prefixed(row, message(e)), seconds(start));
                    }
                }
                BatchResult done = result;
                results.add(done);
                try {
                    csv.append(done);
                } catch (IOException e) {
                    throw new IOException("cannot write " + resultsFile + ": " + IoMessages.reason(e), e);
                }
                quietly(() -> listener.rowFinished(done, index));
                if (fatal != null) {
                    break;
                }
            }
        } finally {
            finished.countDown();
        }
        BatchSummary summary = new BatchSummary(results, rows.size(), cancelled.get() && results.size() < rows.size(),
                fatal, seconds(t0));
        quietly(() -> listener.finished(summary));
        return summary;
    }

    private static ResultsCsv create(Path file) throws IOException {
        try {
            return ResultsCsv.create(file);
        } catch (IOException e) {
            throw new IOException("cannot write " + file + ": " + IoMessages.reason(e), e);
        }
    }

    /** Renders one row and puts its files in place as one set; after a failure none of its new files is there. */
    private List<Path> renderOne(BatchRow row) throws IOException {
        String prefix = outDir.resolve(row.id()).toString();
        if (row.photo() != null) {
            BatchPhoto photo = row.photo();
            return PhotoJob.run(renderer, new PhotoJob.Input(photo.image(), photo.overrides(), null, null, Double.NaN,
                    row.request(), null, prefix), PhotoJob.Log.NONE).files();
        }
        // Opened before rendering: an unwritable destination is found first; close() discards an uncommitted set.
        try (OutputSet set = OutputSet.open(prefix)) {
            set.checkTargets(PanoramaWriter.suffixes(row.request().colour(), row.request().distance(),
                    row.request().layers(), writing));
            Panorama p = renderer.render(row.request());
            List<Path> files = PanoramaWriter.stage(set, p, writing);
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

    private static void quietly(Runnable r) {
        try {
            r.run();
        } catch (RuntimeException e) {
            // a listener's failure is not the batch's
        }
    }
}

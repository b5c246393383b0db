package dempano.batch;

import dempano.PanoramaRenderer;
import dempano.io.IoMessages;
import dempano.io.OutputSet;
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
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
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
 * <p>Row i's files are written on a second thread while row i + 1 is rendered (PNG encoding and
 * drawing overlap); rows are still recorded in order, each once its files are in place, so
 * {@link BatchListener#rowFinished} for row i comes after {@link BatchListener#rowStarted} for row i + 1.
 * At most two panoramas are in memory at a time.
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
        // Row i's files are written on this thread while row i + 1 is rendered; results stay in row order.
        ExecutorService writer = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "dempano-batch-writer");
            t.setDaemon(true);
            return t;
        });
        Pending pending = null;
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
                    OutputSet set = null;
                    try {
                        // Opened before rendering: an unwritable destination is found first.
                        set = OutputSet.open(outDir.resolve(row.id()).toString());
                        set.checkTargets(PanoramaWriter.suffixes(row.request().colour(), row.request().distance(),
                                row.request().layers(), writing));
                        Panorama p = renderer.render(row.request());
                        double renderSeconds = seconds(start);
                        OutputSet handedOver = set;
                        set = null;
                        Future<Written> write = writer.submit(() -> write(handedOver, p));
                        record(pending, csv, results, resultsFile);
                        pending = new Pending(row, index, renderSeconds, write);
                        continue;
                    } catch (RenderFailedException | GlUnavailableException e) {
                        fatal = message(e);
                        result = BatchResult.error(row, prefixed(row, fatal), seconds(start));
                    } catch (OutOfMemoryError e) {
                        result = BatchResult.error(row, prefixed(row, outOfMemory(e)), seconds(start));
                    } catch (IOException e) {
                        result = BatchResult.error(row, prefixed(row, IoMessages.reason(e)), seconds(start));
                    } catch (RuntimeException e) {
                        result = BatchResult.error(row, prefixed(row, message(e)), seconds(start));
                    } finally {
                        if (set != null) {
                            set.close(); // discards what an uncommitted set staged
                        }
                    }
                }
                record(pending, csv, results, resultsFile);
                pending = null;
                record(new Pending(row, index, 0, CompletableFuture.completedFuture(new Written(null, 0, result))), csv,
                        results, resultsFile);
                if (fatal != null) {
                    break;
                }
            }
            record(pending, csv, results, resultsFile);
            pending = null;
        } finally {
            writer.shutdown();
            try {
                // Only after a failure of results.csv: the row being written is finished, not cut off.
                writer.awaitTermination(1, TimeUnit.MINUTES);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            finished.countDown();
        }
        BatchSummary summary = new BatchSummary(results, rows.size(), cancelled.get() && results.size() < rows.size(),
                fatal, seconds(t0));
        quietly(() -> listener.finished(summary));
        return summary;
    }

    /** A row rendered and being written: its result is recorded once the write has ended. */
    private record Pending(BatchRow row, int index, double renderSeconds, Future<Written> write) {
    }

    /** What a write gave: the files and its seconds, or (for rows that failed earlier) the result itself. */
    private record Written(List<Path> files, double seconds, BatchResult result) {
    }

    /** On the writer thread: the row's files staged and committed as one set (discarded after a failure). */
    private Written write(OutputSet set, Panorama p) throws IOException {
        long start = System.nanoTime();
        try (set) {
            List<Path> files = PanoramaWriter.stage(set, p, writing);
            set.commit();
            return new Written(files, seconds(start), null);
        }
    }

    /** Waits for a pending row's write, appends its line to results.csv and tells the listener; no-op for null. */
    private void record(Pending pending, ResultsCsv csv, List<BatchResult> results, Path resultsFile) throws IOException {
        if (pending == null) {
            return;
        }
        BatchRow row = pending.row();
        BatchResult result;
        try {
            Written w = getUninterruptibly(pending.write());
            result = w.result() != null ? w.result() : BatchResult.ok(row, w.files(), pending.renderSeconds() + w.seconds());
        } catch (ExecutionException e) {
            Throwable c = e.getCause();
            String why = c instanceof IOException io ? IoMessages.reason(io)
                    : c instanceof OutOfMemoryError oom ? outOfMemory(oom) : message(c);
            result = BatchResult.error(row, prefixed(row, why), pending.renderSeconds());
        }
        results.add(result);
        try {
            csv.append(result);
        } catch (IOException e) {
            throw new IOException("cannot write " + resultsFile + ": " + IoMessages.reason(e), e);
        }
        BatchResult done = result;
        quietly(() -> listener.rowFinished(done, pending.index()));
    }

    private static <T> T getUninterruptibly(Future<T> f) throws ExecutionException {
        boolean interrupted = false;
        try {
            while (true) {
                try {
                    return f.get();
                } catch (InterruptedException e) {
                    interrupted = true;
                }
            }
        } finally {
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }
    }

    private static String outOfMemory(OutOfMemoryError e) {
        return "out of memory (" + e.getMessage() + "): lower ppd or range, or give Java more memory (DEMPANO_OPTS=-Xmx…)";
    }

    private static ResultsCsv create(Path file) throws IOException {
        try {
            return ResultsCsv.create(file);
        } catch (IOException e) {
            throw new IOException("cannot write " + file + ": " + IoMessages.reason(e), e);
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

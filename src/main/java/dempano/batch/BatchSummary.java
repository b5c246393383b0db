package dempano.batch;

import java.util.List;

/**
 * The outcome of a batch.
 *
 * @param results      one per row handled, in row order (rows not reached after a cancellation or a
 *                     renderer failure are absent)
 * @param rows         rows in the batch
 * @param cancelled    the batch stopped early because {@link BatchRun#cancel()} was called
 * @param fatal        why the batch stopped early when the renderer itself failed (no OpenGL, a GL
 *                     thread failure); null otherwise
 * @param seconds      wall-clock time of the whole batch, seconds
 */
public record BatchSummary(List<BatchResult> results, int rows, boolean cancelled, String fatal, double seconds) {
    public BatchSummary {
        results = List.copyOf(results);
    }

    public long okCount() {
        return results.stream().filter(BatchResult::ok).count();
    }

    public long errorCount() {
        return results.size() - okCount();
    }

    /** Rows not handled (cancelled, or after a renderer failure). */
    public int notRun() {
        return rows - results.size();
    }

    /** Every row was rendered and written. */
    public boolean allOk() {
        return okCount() == rows;
    }

    /** Mean seconds per rendered panorama (OK rows), NaN when none. */
    public double secondsPerPanorama() {
        return results.stream().filter(BatchResult::ok).mapToDouble(BatchResult::seconds).average().orElse(Double.NaN);
    }
}

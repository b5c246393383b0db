package dempano.batch;

/**
 * Told of a batch's progress: on the thread that runs the batch, but {@link #rowFinished} of a panorama row on the
 * batch's writer thread (as soon as its files are in place, while the next row renders). Never two calls at once (the
 * batch calls it holding the listener's own lock), rows finished in row order. Every method has an empty default.
 * A listener that throws stops nothing: the exception or error (an AssertionError, say) is ignored by the batch.
 */
public interface BatchListener {
    /** Before the first row: the number of rows (valid or not). */
    default void started(int rows) {
    }

    /** Before a row is rendered (also for rows that are rejected unread); {@code index} counts from 0. */
    default void rowStarted(BatchRow row, int index) {
    }

    /** After a row's files are in place (or it failed) and its line is in {@code results.csv}. */
    default void rowFinished(BatchResult result, int index) {
    }

    /** After the last row, or when the batch stops early (cancelled, or the renderer failed). */
    default void finished(BatchSummary summary) {
    }
}

package dempano.batch;

import java.nio.file.Path;
import java.util.List;
import java.util.Objects;

/**
 * What became of one row of a batch.
 *
 * @param id         the row's id as given
 * @param lineNumber the row's line in the viewpoint file (0 for rows made in code)
 * @param status     {@link Status#OK} when the row's files are in place, {@link Status#ERROR} otherwise
 * @param files      the files written, {@code <id>.json} last (empty for an error: a failed row leaves no new file)
 * @param seconds    wall-clock time spent on the row: rendering and writing, seconds (0 for rows rejected unread)
 * @param error      one line saying what went wrong; null when OK
 */
public record BatchResult(String id, int lineNumber, Status status, List<Path> files, double seconds, String error) {
    /** A row's outcome, as written in {@code results.csv}: {@code ok} or {@code error}. */
    public enum Status {
        OK, ERROR;

        /** The word in {@code results.csv}. */
        public String word() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    public BatchResult {
        Objects.requireNonNull(id, "id");
        Objects.requireNonNull(status, "status");
        files = List.copyOf(files);
        if ((status == Status.OK) != (error == null)) {
            throw new IllegalArgumentException("an error result needs a message, an OK one has none");
        }
    }

    static BatchResult ok(BatchRow row, List<Path> files, double seconds) {
        return new BatchResult(row.id(), row.lineNumber(), Status.OK, files, seconds, null);
    }

    static BatchResult error(BatchRow row, String message, double seconds) {
        return new BatchResult(row.id(), row.lineNumber(), Status.ERROR, List.of(), seconds, ViewpointCsv.oneLine(message));
    }

    public boolean ok() {
        return status == Status.OK;
    }
}

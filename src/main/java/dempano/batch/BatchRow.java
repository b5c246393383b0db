package dempano.batch;

import dempano.PanoramaRequest;
import java.util.Objects;

/**
 * One row of a batch: an output id and the panorama (or photograph's view) to render for it, or why the row cannot
 * be rendered (a bad number, a coordinate out of range, an unsafe or repeated id). A row that
 * cannot be rendered is reported in the results as an error; the rest of the batch goes on.
 *
 * @param lineNumber the line of the viewpoint file the row starts on (1 = the header line); 0 for
 *                   rows made in code
 * @param id         the output id as given (never null; may be empty or unsafe when {@code error} says so);
 *                   the row's files are {@code D/<id>.png}, {@code D/<id>-distance.npy}, …
 * @param request    what to render (for a photo row: the render settings, range, refraction, ...); null exactly
 *                   when {@code error} is set
 * @param photo      for a photo row, the photograph and its camera values from the row; null for a viewpoint
 *                   (a panorama) and for an invalid row
 * @param error      one line saying why the row cannot be rendered; null for a valid row
 */
public record BatchRow(int lineNumber, String id, PanoramaRequest request, BatchPhoto photo, String error) {
    public BatchRow {
        Objects.requireNonNull(id, "id");
        if ((request == null) == (error == null)) {
            throw new IllegalArgumentException("a batch row has a request or an error, exactly one of them");
        }
        if (photo != null && request == null) {
            throw new IllegalArgumentException("a photo row has its render settings");
        }
        if (lineNumber < 0) {
            throw new IllegalArgumentException("line number must be ≥ 0, got " + lineNumber);
        }
    }

    /** A row made in code (line number 0); the id is checked when the batch runs. */
    public static BatchRow of(String id, PanoramaRequest request) {
        return new BatchRow(0, id, Objects.requireNonNull(request, "request"), null, null);
    }

    /** A photo row made in code (line number 0): the photo rendered with these settings. */
    public static BatchRow photo(String id, BatchPhoto photo, PanoramaRequest settings) {
        return new BatchRow(0, id, Objects.requireNonNull(settings, "settings"), Objects.requireNonNull(photo, "photo"), null);
    }

    /** A row that cannot be rendered, with the reason (one line). */
    public static BatchRow invalid(int lineNumber, String id, String error) {
        return new BatchRow(lineNumber, id == null ? "" : id, null, null, Objects.requireNonNull(error, "error"));
    }

    /** True when the row has a request (no error). */
    public boolean valid() {
        return request != null;
    }

    /** "line N" for rows from a file, "row 'id'" for rows made in code: where a message points the reader. */
    public String where() {
        return lineNumber > 0 ? "line " + lineNumber : "row '" + id + "'";
    }
}

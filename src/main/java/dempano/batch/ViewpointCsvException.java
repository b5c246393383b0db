package dempano.batch;

import java.io.IOException;

/** A viewpoint file that cannot be used at all (unreadable, no header, a required column missing); the message is one line. */
public final class ViewpointCsvException extends IOException {
    public ViewpointCsvException(String message) {
        super(message);
    }

    public ViewpointCsvException(String message, Throwable cause) {
        super(message, cause);
    }
}

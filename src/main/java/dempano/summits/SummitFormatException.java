package dempano.summits;

/** A summit list that cannot be read: the message names the file, the line and the problem. */
public class SummitFormatException extends RuntimeException {
    public SummitFormatException(String message) {
        super(message);
    }

    public SummitFormatException(String message, Throwable cause) {
        super(message, cause);
    }
}

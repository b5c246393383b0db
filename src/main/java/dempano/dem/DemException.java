package dempano.dem;

/** A DEM input problem (bad, missing or unreadable tile); the message names the file and the problem. */
public class DemException extends RuntimeException {
    public DemException(String message) {
        super(message);
    }

    public DemException(String message, Throwable cause) {
        super(message, cause);
    }
}
